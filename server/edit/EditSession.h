#pragma once
// One open model being edited: applies the WebSocket editing requests (model.get,
// component.*, connect, disconnect, parameter.*, sysparam.*, model.settings,
// model.controls, model.group, model.ungroup) to an in-memory Model.
// It knows nothing of users, stores or sockets; the caller loads and saves the .hmf text.
//
// Requests arrive schema-validated, but handle() still checks every field it reads and
// never throws: a bad request becomes a Result with a stable error code.
#include "core/Model.h"
#include "server/protocol/Messages.generated.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

class EditSession {
public:
    // Replaces any open model. Fails (error = the loader's message) only when the model
    // cannot be built at all; problems the loader could work around are in loadMessages().
    bool openHmf(const std::string& hmf, const std::string& name, std::string& error);
    void createEmpty(const std::string& name);
    void close();

    struct Result {
        bool ok = true;
        nlohmann::json data = nlohmann::json::object();
        std::string code, message;
    };
    Result handle(const nlohmann::json& request);

    std::string saveHmf() const;   // empty if nothing is open
    bool isOpen() const { return mModel.has_value(); }

    const std::string& name() const { return mName; }
    void setName(const std::string& name) { mName = name; }
    protocol::Model model() const;   // the open model as the protocol shows it; isOpen() first
    // The open model (null if none), e.g. for starting a simulation of its current state.
    const Model* openModel() const { return mModel ? &*mModel : nullptr; }
    const std::vector<Message>& loadMessages() const { return mLoadMessages; }

private:
    Result modelGet();
    Result componentAdd(System& system, const protocol::ComponentAddRequest& request);
    Result componentRemove(System& system, const protocol::ComponentRemoveRequest& request);
    Result componentRename(System& system, const protocol::ComponentRenameRequest& request);
    Result componentMove(System& system, const protocol::ComponentMoveRequest& request);
    Result connect(System& system, const protocol::ConnectRequest& request);
    Result disconnect(System& system, const protocol::DisconnectRequest& request);
    Result connectionRoute(System& system, const protocol::ConnectionRouteRequest& request);
    Result parameterGet(System& system, const protocol::ParameterGetRequest& request);
    Result parameterSet(System& system, const protocol::ParameterSetRequest& request);
    Result sysparamSet(System& system, const protocol::SysParamSetRequest& request);
    Result sysparamRemove(System& system, const protocol::SysParamRemoveRequest& request);
    Result modelSettings(System& system, const protocol::ModelSettingsRequest& request);
    Result modelControls(System& system, const protocol::ModelControlsRequest& request);
    Result modelGroup(System& system, const protocol::ModelGroupRequest& request);
    Result modelUngroup(System& system, const protocol::ModelUngroupRequest& request);

    // The subsystem named by request["system"] (absent or [] = root), or null with `failure`.
    System* targetSystem(const nlohmann::json& request, Result& failure);

    std::optional<Model> mModel;
    std::string mName;
    std::vector<Message> mLoadMessages;
};

} // namespace tlmhub::server
