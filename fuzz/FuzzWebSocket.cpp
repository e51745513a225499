// Fuzzes WebSocket messages through the dispatcher (WsApi) of a real TlmhubApp, without a
// network. An input is a sequence of messages separated by 0x1E (the record separator of
// JSON text sequences, RFC 7464), all sent on one connection of the admin. Every frame the
// server sends back must be a JSON object with a type.
#include "fuzz/FuzzServer.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string_view>
#include <vector>

namespace {

using namespace tlmhub;

class CheckingSender : public server::WebSocketSender {
public:
    void send(std::string text) override
    {
        const nlohmann::json frame = nlohmann::json::parse(text, nullptr, false);
        if (!frame.is_object() || !frame.contains("type")) fuzz::fail("server sent a frame that is not a message: " + text);
    }
    void sendFrame(std::unique_ptr<server::MergeableFrame> frame) override { send(frame->text()); }
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

    std::string_view rest(reinterpret_cast<const char*>(data), size);
    while (true) {
        const std::size_t end = rest.find('\x1e');
        handler->onMessage(std::string(rest.substr(0, end)));
        sender->runPending();
        if (end == std::string_view::npos) break;
        rest.remove_prefix(end + 1);
    }
    sender->runPending();
    handler->onClose();
    return 0;
}
