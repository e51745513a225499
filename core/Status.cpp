#include "core/Status.h"

namespace tlmhub {

const char* statusCodeName(StatusCode code)
{
    switch (code) {
    case StatusCode::Ok: return "ok";
    case StatusCode::UnknownComponentType: return "unknown_component_type";
    case StatusCode::IllegalConnection: return "illegal_connection";
    case StatusCode::UnconnectedPort: return "unconnected_port";
    case StatusCode::UndefinedKind: return "undefined_kind";
    case StatusCode::InvalidParameter: return "invalid_parameter";
    case StatusCode::UnknownParameter: return "unknown_parameter";
    case StatusCode::InvalidSettings: return "invalid_settings";
    case StatusCode::AlgebraicLoop: return "algebraic_loop";
    case StatusCode::InitFailed: return "init_failed";
    case StatusCode::SimulationStopped: return "simulation_stopped";
    case StatusCode::SimulationEnded: return "simulation_ended";
    case StatusCode::InvalidState: return "invalid_state";
    case StatusCode::NotFound: return "not_found";
    case StatusCode::IllegalGrouping: return "illegal_grouping";
    case StatusCode::IoError: return "io_error";
    case StatusCode::InvalidModel: return "invalid_model";
    case StatusCode::RestartRequired: return "restart_required";
    }
    return "unknown";
}

std::string describe(const Status& status)
{
    std::string text = std::string(status.codeName()) + ": " + status.message();
    if (!status.path().empty()) text += " (at " + status.path() + ")";
    return text;
}

} // namespace tlmhub
