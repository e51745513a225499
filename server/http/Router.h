#pragma once
// Maps "METHOD /path/{param}/..." patterns to handlers. Path parameters are captured by
// name; the query string is parsed into a map. A path that matches with another method
// gives 405, no match 404 (decided by the caller from `Match`).
#include "server/http/HttpTypes.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace tlmhub::server {

struct RouteParams {
    std::map<std::string, std::string> path;    // {id} -> "42"
    std::map<std::string, std::string> query;   // ?format=csv -> format=csv (percent-decoded)
    std::string pathOnly;                       // target without the query
};

// '+' means a space only in query strings.
std::string percentDecode(const std::string& text, bool plusIsSpace);
RouteParams parseRequestTarget(const std::string& target);
std::vector<std::string> splitPath(const std::string& path);

template <typename Handler>
class Router {
public:
    void add(http::verb method, const std::string& pattern, Handler handler)
    {
        mRoutes.push_back({method, splitPath(pattern), std::move(handler)});
    }

    enum class Match { Found, WrongMethod, None };

    // On Found, `handler` points at the route's handler and `params` is filled.
    Match find(http::verb method, const std::string& target, const Handler*& handler,
               RouteParams& params) const
    {
        params = parseRequestTarget(target);
        const std::vector<std::string> segments = splitPath(params.pathOnly);
        bool pathMatched = false;
        for (const Route& r : mRoutes) {
            std::map<std::string, std::string> captured;
            if (!matches(r.segments, segments, captured)) continue;
            pathMatched = true;
            if (r.method != method) continue;
            params.path = std::move(captured);
            handler = &r.handler;
            return Match::Found;
        }
        return pathMatched ? Match::WrongMethod : Match::None;
    }

private:
    struct Route {
        http::verb method;
        std::vector<std::string> segments;
        Handler handler;
    };

    static bool matches(const std::vector<std::string>& pattern,
                        const std::vector<std::string>& segments,
                        std::map<std::string, std::string>& captured)
    {
        if (pattern.size() != segments.size()) return false;
        for (std::size_t i = 0; i < pattern.size(); ++i) {
            const std::string& p = pattern[i];
            if (p.size() > 2 && p.front() == '{' && p.back() == '}')
                captured[p.substr(1, p.size() - 2)] = segments[i];
            else if (p != segments[i])
                return false;
        }
        return true;
    }

    std::vector<Route> mRoutes;
};


} // namespace tlmhub::server
