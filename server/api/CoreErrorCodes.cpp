#include "server/api/CoreErrorCodes.h"

namespace tlmhub::server {

const char* protocolErrorCode(StatusCode code)
{
    switch (code) {
    case StatusCode::UnknownComponentType: return "unknown_component_type";
    case StatusCode::IllegalConnection: return "illegal_connection";
    case StatusCode::IllegalGrouping: return "illegal_grouping";
    case StatusCode::InvalidParameter:
    case StatusCode::UnknownParameter: return "invalid_parameter";
    case StatusCode::InvalidModel:
    case StatusCode::UnconnectedPort:
    case StatusCode::UndefinedKind:
    case StatusCode::AlgebraicLoop: return "invalid_model";
    case StatusCode::InvalidSettings: return "bad_request";
    case StatusCode::InitFailed:
    case StatusCode::SimulationStopped:
    case StatusCode::SimulationEnded: return "simulation_failed";
    case StatusCode::InvalidState:
    case StatusCode::RestartRequired: return "restart_required";
    case StatusCode::NotFound: return "not_found";
    case StatusCode::Ok:   // a success is no error: reaching here is a bug
    case StatusCode::IoError: return "internal";
    }
    return "internal";
}

} // namespace tlmhub::server
