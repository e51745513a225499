#pragma once
// TLS for the servers tests start on loopback: a CA made for the test, a certificate it signs
// for 127.0.0.1, and a second CA that signed nothing (to check that only the right one is
// trusted). Made with Debian's openssl; throws naming the step that failed.
#include <filesystem>

namespace tlmhub::test {

// Writes ca.pem, other-ca.pem, cert.pem and key.pem (the certificate's private key) to `dir`.
void makeTestCertificates(const std::filesystem::path& dir);

} // namespace tlmhub::test
