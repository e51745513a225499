#pragma once
// Precompiled for every server source (server/CMakeLists.txt): the large headers most of
// them include, directly or through their own headers, so each is parsed once per build
// instead of once per file.
#include <boost/asio/post.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>
#include <pqxx/pqxx>
#include <SQLiteCpp/SQLiteCpp.h>

#include "server/OptimisedJson.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>
