// The non-template parts of Boost.Asio's TLS streams, compiled once (net/CMakeLists.txt says
// why); only the CLI's remote commands speak TLS.
#include <boost/asio/ssl/impl/src.hpp>
