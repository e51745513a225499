#pragma once
// Precompiled for the server tests under clang (tests/CMakeLists.txt): the large headers
// nearly all of them include, parsed once instead of once per file.
#include <gtest/gtest.h>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>

#include "server/OptimisedJson.h"

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>
