#include "server/protocol/UntrustedJson.h"

namespace tlmhub::server {

namespace {

// A SAX pass that builds nothing: it checks the syntax and stops at the first container
// that opens past the depth limit.
class DepthCheck : public nlohmann::json_sax<nlohmann::json> {
public:
    explicit DepthCheck(std::size_t maxDepth) : mMaxDepth(maxDepth) {}

    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return open(); }
    bool key(string_t&) override { return true; }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(); }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception&) override
    {
        mErrorAt = position;
        return false;
    }

    bool tooDeep() const { return mTooDeep; }
    std::size_t errorAt() const { return mErrorAt; }

private:
    bool open()
    {
        if (++mDepth <= mMaxDepth) return true;
        mTooDeep = true;
        return false;
    }
    bool close()
    {
        --mDepth;
        return true;
    }

    std::size_t mMaxDepth;
    std::size_t mDepth = 0;
    bool mTooDeep = false;
    std::size_t mErrorAt = 0;
};

} // namespace

UntrustedJson parseUntrustedJson(std::string_view text, std::size_t maxDepth)
{
    UntrustedJson out;
    DepthCheck check(maxDepth);
    if (!nlohmann::json::sax_parse(text, &check)) {
        out.value = nlohmann::json(nlohmann::json::value_t::discarded);
        if (check.tooDeep()) {
            out.error = "JSON is nested more than " + std::to_string(maxDepth) + " levels deep";
        } else {
            out.error = "not valid JSON (at byte " + std::to_string(check.errorAt()) + ")";
        }
        return out;
    }
    out.value = nlohmann::json::parse(text);
    return out;
}

} // namespace tlmhub::server
