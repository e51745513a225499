// Replies stay JSON when the text they echo is not valid UTF-8.
#include "server/api/ApiSupport.h"
#include "server/http/JsonText.h"

#include <gtest/gtest.h>

using namespace tlmhub::server;

// Found by fuzz/FuzzRest: the 404 for a path with a byte 0xB4 threw from dump() instead of
// answering (the transport turned it into a 500).
TEST(JsonText, ErrorEchoingInvalidUtf8IsStillJson)
{
    Response res;
    ASSERT_NO_THROW(res = apiError(http::status::not_found, "not_found", "no API route /models/\xb4"));
    const nlohmann::json body = nlohmann::json::parse(res.body(), nullptr, false);
    ASSERT_FALSE(body.is_discarded()) << res.body();
    EXPECT_EQ(body["error"]["message"], "no API route /models/\xef\xbf\xbd");   // U+FFFD
}

TEST(JsonText, ValidTextIsUnchanged)
{
    EXPECT_EQ(toJsonText({{"name", "Tank \xc3\xa5"}}), "{\"name\":\"Tank \xc3\xa5\"}");
}
