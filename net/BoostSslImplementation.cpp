// The non-template parts of Boost.Asio's TLS streams, compiled once (net/CMakeLists.txt says
// why): the TLS of the HTTP client (the CLI's remote commands, the server's calls to OpenID providers).
#include <boost/asio/ssl/impl/src.hpp>
