// Fuzzes WebSocket messages through the dispatcher (WsApi) of a real TlmhubApp, without a
// network. An input is a sequence of messages separated by 0x1E (the record separator of
// JSON text sequences, RFC 7464), all sent on one connection of the admin. Every frame the
// server sends back must be a JSON object with a type.
#include "fuzz/FuzzServer.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <mutex>
#include <string_view>
#include <thread>
#include <vector>

namespace {

using namespace tlmhub;

class CheckingSender : public server::WebSocketSender {
public:
    void send(std::string text) override
    {
        const nlohmann::json frame = nlohmann::json::parse(text, nullptr, false);
        if (!frame.is_object() || !frame.contains("type")) fuzz::fail("server sent a frame that is not a message: " + text);
        if (frame["type"] == "reply" || frame["type"] == "error") ++mAnswers;
    }
    // Progress events: checked as any message (the fuzz loop reads everything at once, so
    // none is ever replaced).
    void sendReplaceable(std::string, std::string text) override { send(std::move(text)); }
    void sendFrame(std::unique_ptr<server::MergeableFrame> frame) override
    {
        const server::OutgoingMessage message = frame->message();
        if (!message.binary) return send(message.data);
        std::uint32_t headerBytes = 0;
        if (message.data.size() >= 4) std::memcpy(&headerBytes, message.data.data(), 4);
        if (message.data.size() < 4 + std::size_t{headerBytes} ||
            !nlohmann::json::accept(message.data.substr(4, headerBytes)))
            fuzz::fail("server sent a binary frame without a JSON header");
    }
    // Replies and errors sent: every message gets exactly one.
    std::size_t answers() const { return mAnswers; }
    void close(std::string) override {}
    // The connection's strand is the fuzz loop: tasks (a submitted job's reply) run between
    // messages; those that come after the input ended are dropped, as on a closed socket.
    void runOnConnection(std::function<void()> task) override
    {
        std::lock_guard lock(mMutex);
        mTasks.push_back(std::move(task));
    }
    void runPending()
    {
        std::vector<std::function<void()>> tasks;
        {
            std::lock_guard lock(mMutex);
            tasks.swap(mTasks);
        }
        for (auto& task : tasks) task();
    }

private:
    std::mutex mMutex;
    std::vector<std::function<void()>> mTasks;
    std::atomic<std::size_t> mAnswers{0};
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    fuzz::FuzzServer& server = fuzz::FuzzServer::instance();
    server::Request upgrade{server::http::verb::get, "/api/v1/ws", 11};
    upgrade.set(server::http::field::authorization, "Bearer " + server.token());
    server::Response refusal;
    auto sender = std::make_shared<CheckingSender>();
    auto handler = server.app().acceptWebSocket({upgrade, "127.0.0.1"}, sender, refusal);
    if (!handler) fuzz::fail("WebSocket refused: " + refusal.body());

    // Some requests are handled on the app's request pool and answered through
    // runOnConnection: each message's answer is awaited before the next is sent.
    std::string_view rest(reinterpret_cast<const char*>(data), size);
    for (std::size_t sent = 1;; ++sent) {
        const std::size_t end = rest.find('\x1e');
        handler->onMessage(std::string(rest.substr(0, end)));
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        for (sender->runPending(); sender->answers() < sent; sender->runPending()) {
            if (std::chrono::steady_clock::now() > deadline) fuzz::fail("a message got no answer within 60 s");
            std::this_thread::sleep_for(std::chrono::microseconds(100));
        }
        if (sender->answers() > sent) fuzz::fail("a message got more than one answer");
        if (end == std::string_view::npos) break;
        rest.remove_prefix(end + 1);
    }
    sender->runPending();
    handler->onClose();
    return 0;
}
