// The non-template parts of Boost.Asio and Boost.Beast, compiled once for the whole program
// (BOOST_ASIO_SEPARATE_COMPILATION, BOOST_BEAST_SEPARATE_COMPILATION; see CMakeLists.txt).
// TLS (boost/asio/ssl) is compiled where it is used: cli/remote/BoostSslImplementation.cpp.
#include <boost/asio/impl/src.hpp>
#include <boost/beast/src.hpp>
