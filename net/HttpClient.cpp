#include "net/HttpClient.h"

#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/ssl.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/ssl.hpp>
#include <openssl/ssl.h>
#include <openssl/x509_vfy.h>

#include <optional>

namespace tlmhub::net {

namespace beast = boost::beast;
namespace http = beast::http;
namespace asio = boost::asio;
namespace ssl = asio::ssl;
using tcp = asio::ip::tcp;

namespace {

http::verb verbOf(HttpMethod method)
{
    switch (method) {
    case HttpMethod::Get: return http::verb::get;
    case HttpMethod::Post: return http::verb::post;
    case HttpMethod::Delete: return http::verb::delete_;
    }
    return http::verb::get;
}

} // namespace

// Each operation is started asynchronously and the io_context run until it completes: that
// is what lets the stream's deadline (tcp_stream::expires_after) bound a blocking call.
class HttpClient::Connection {
public:
    Connection(Url server, HttpLimits limits, const std::filesystem::path& caFile);
    HttpResponse send(const HttpRequest& request);
    const Url& server() const { return mServer; }

private:
    struct Failure {
        std::string stage;       // "sending the request", "reading the response"
        beast::error_code error;
        bool answered = false;   // some of a response arrived
    };

    void connect();
    void close();
    std::string tlsFailure(const beast::error_code& error) const;
    template <class Stream>
    std::optional<HttpResponse> exchange(Stream& stream, http::request<http::string_body>& request, Failure& failure);
    template <class Start>
    beast::error_code complete(Start start);
    beast::tcp_stream& tcpStream() { return mSecure ? beast::get_lowest_layer(*mSecure) : *mPlain; }
    std::string describe(const beast::error_code& error, std::chrono::seconds deadline) const;

    Url mServer;
    HttpLimits mLimits;
    asio::io_context mIoc;
    ssl::context mTls{ssl::context::tls_client};
    std::unique_ptr<beast::tcp_stream> mPlain;
    std::unique_ptr<beast::ssl_stream<beast::tcp_stream>> mSecure;
    beast::flat_buffer mBuffer;
};

HttpClient::Connection::Connection(Url server, HttpLimits limits, const std::filesystem::path& caFile)
    : mServer(std::move(server)), mLimits(limits)
{
    if (!mServer.secure) return;
    beast::error_code error;
    if (!caFile.empty()) {
        mTls.load_verify_file(caFile.string(), error);
        if (error) throw ConnectionError("cannot load the CA file " + caFile.string() + ": " + error.message());
    } else {
        // The system's certificate store; OpenSSL reads SSL_CERT_FILE and SSL_CERT_DIR here.
        mTls.set_default_verify_paths(error);
        if (error) throw ConnectionError("cannot load the system's certificate store: " + error.message());
    }
    mTls.set_verify_mode(ssl::verify_peer);
    SSL_CTX_set_min_proto_version(mTls.native_handle(), TLS1_2_VERSION);
}

template <class Start>
beast::error_code HttpClient::Connection::complete(Start start)
{
    beast::error_code result;
    start([&result](const beast::error_code& error, auto&&...) { result = error; });
    mIoc.restart();
    mIoc.run();
    return result;
}

std::string HttpClient::Connection::describe(const beast::error_code& error, std::chrono::seconds deadline) const
{
    if (error == beast::error::timeout) return "no answer within " + std::to_string(deadline.count()) + " s";
    return error.message();
}

void HttpClient::Connection::connect()
{
    tcp::resolver resolver(mIoc);
    beast::error_code error;
    const tcp::resolver::results_type endpoints = resolver.resolve(mServer.host, mServer.port, error);
    if (error) throw ConnectionError("cannot resolve " + mServer.host + ": " + error.message());

    if (mServer.secure) {
        mSecure = std::make_unique<beast::ssl_stream<beast::tcp_stream>>(mIoc, mTls);
        SSL* tls = mSecure->native_handle();
        beast::error_code notAddress;
        asio::ip::make_address(mServer.host, notAddress);
        // SNI carries host names only (RFC 6066). OpenSSL checks the certificate's names
        // while verifying it, so a mismatch fails the handshake with its own reason.
        if (notAddress) {
            SSL_set_tlsext_host_name(tls, mServer.host.c_str());
            SSL_set1_host(tls, mServer.host.c_str());
        } else {
            X509_VERIFY_PARAM_set1_ip_asc(SSL_get0_param(tls), mServer.host.c_str());
        }
    } else {
        mPlain = std::make_unique<beast::tcp_stream>(mIoc);
    }
    beast::tcp_stream& stream = tcpStream();
    stream.expires_after(mLimits.connect);
    error = complete([&](auto handler) { stream.async_connect(endpoints, std::move(handler)); });
    if (error) {
        close();
        throw ConnectionError("cannot connect to " + mServer.authority() + ": " + describe(error, mLimits.connect));
    }
    if (!mSecure) return;
    stream.expires_after(mLimits.connect);
    error = complete([&](auto handler) { mSecure->async_handshake(ssl::stream_base::client, std::move(handler)); });
    if (error) {
        const std::string reason = tlsFailure(error);
        close();
        throw ConnectionError("TLS handshake with " + mServer.authority() + " failed: " + reason);
    }
}

std::string HttpClient::Connection::tlsFailure(const beast::error_code& error) const
{
    const long verified = SSL_get_verify_result(mSecure->native_handle());
    if (verified == X509_V_OK) return describe(error, mLimits.connect);
    if (verified == X509_V_ERR_HOSTNAME_MISMATCH || verified == X509_V_ERR_IP_ADDRESS_MISMATCH)
        return "the server's certificate is not for " + mServer.host + " (" + X509_verify_cert_error_string(verified) +
               ")";
    return std::string("the server's certificate is not trusted: ") + X509_verify_cert_error_string(verified) +
           " (SSL_CERT_FILE can name a file of certificates to trust)";
}

void HttpClient::Connection::close()
{
    // Dropping the stream closes the socket; a TLS close_notify could wait on the peer.
    mSecure.reset();
    mPlain.reset();
    mBuffer.clear();
}

template <class Stream>
std::optional<HttpResponse> HttpClient::Connection::exchange(Stream& stream, http::request<http::string_body>& request,
                                                             Failure& failure)
{
    // Piece by piece, each with a fresh deadline: a large upload or download may take long,
    // but never waits longer than `idle` for the next bytes.
    http::request_serializer<http::string_body> serializer(request);
    while (!serializer.is_done()) {
        tcpStream().expires_after(mLimits.idle);
        failure.error = complete([&](auto handler) { http::async_write_some(stream, serializer, std::move(handler)); });
        if (failure.error) {
            failure.stage = "sending the request";
            return std::nullopt;
        }
    }
    http::response_parser<http::string_body> parser;
    parser.body_limit(mLimits.maxResponseBytes);
    while (!parser.is_done()) {
        tcpStream().expires_after(mLimits.idle);
        failure.error =
            complete([&](auto handler) { http::async_read_some(stream, mBuffer, parser, std::move(handler)); });
        if (failure.error) {
            failure.stage = "reading the response";
            failure.answered = parser.got_some();
            return std::nullopt;
        }
    }
    http::response<http::string_body> response = parser.release();
    if (!response.keep_alive()) close();
    HttpResponse out{static_cast<int>(response.result_int()), std::move(response.body()), {}};
    for (const auto& field : response)
        out.headers.emplace_back(std::string(field.name_string()), std::string(field.value()));
    return out;
}

HttpResponse HttpClient::Connection::send(const HttpRequest& request)
{
    http::request<http::string_body> message{verbOf(request.method), request.target, 11};
    message.set(http::field::host, mServer.authority());
    message.set(http::field::user_agent, request.userAgent);
    if (!request.bearerToken.empty()) message.set(http::field::authorization, "Bearer " + request.bearerToken);
    if (!request.contentType.empty()) message.set(http::field::content_type, request.contentType);
    for (const auto& [name, value] : request.headers) message.set(name, value);
    message.body() = request.body;
    message.prepare_payload();

    for (int attempt = 0;; ++attempt) {
        const bool kept = mPlain || mSecure;
        if (!kept) connect();
        Failure failure;
        std::optional<HttpResponse> response =
            mSecure ? exchange(*mSecure, message, failure) : exchange(*mPlain, message, failure);
        if (response) return std::move(*response);
        close();
        // A kept connection that the server has closed meanwhile (its idle timeout) fails
        // before any answer: one more try on a new connection. The server closes only
        // connections it is not reading a request from, so this does not send a POST twice.
        if (kept && !failure.answered && attempt == 0) continue;
        if (failure.error == http::error::body_limit)
            throw ConnectionError("the response from " + mServer.authority() + " is over the limit of " +
                                  std::to_string(mLimits.maxResponseBytes) + " bytes");
        throw ConnectionError("connection to " + mServer.authority() + " failed while " + failure.stage + ": " +
                              describe(failure.error, mLimits.idle));
    }
}

HttpClient::HttpClient(Url server, HttpLimits limits, const std::filesystem::path& caFile)
    : mConnection(std::make_unique<Connection>(std::move(server), limits, caFile))
{
}

HttpClient::~HttpClient() = default;

std::string HttpResponse::header(std::string_view name) const
{
    for (const auto& [field, value] : headers)
        if (beast::iequals(field, name)) return value;
    return {};
}

HttpResponse HttpClient::send(const HttpRequest& request) { return mConnection->send(request); }

const Url& HttpClient::server() const { return mConnection->server(); }

} // namespace tlmhub::net
