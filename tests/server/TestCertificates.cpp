#include "TestCertificates.h"

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace tlmhub::test {

void makeTestCertificates(const std::filesystem::path& dir)
{
    const auto run = [&](const std::string& command) {
        const std::string line = "cd '" + dir.string() + "' && " + command + " >>openssl.log 2>&1";
        if (std::system(line.c_str()) != 0)
            throw std::runtime_error("making the test certificates failed (apt-get install openssl): " + command);
    };
    for (const std::string ca : {"ca", "other-ca"})
        run("/usr/bin/openssl req -x509 -newkey rsa:2048 -nodes -keyout " + ca + ".key -out " + ca +
            ".pem -days 2 -subj /CN=tlmhub-test-" + ca);
    run("/usr/bin/openssl req -newkey rsa:2048 -nodes -keyout key.pem -out request.csr -subj /CN=127.0.0.1");
    run("printf 'subjectAltName=IP:127.0.0.1\\n' >san.ext && /usr/bin/openssl x509 -req -in request.csr -CA ca.pem"
        " -CAkey ca.key -CAcreateserial -out cert.pem -days 2 -extfile san.ext");
}

} // namespace tlmhub::test
