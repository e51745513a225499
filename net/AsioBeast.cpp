// The compiled part of Boost.Asio (with its TLS streams) and Boost.Beast, once for the whole
// project (net/CMakeLists.txt).
#include <boost/asio/impl/src.hpp>
#include <boost/asio/ssl/impl/src.hpp>
#include <boost/beast/src.hpp>
