#pragma once
namespace tlmhub::server {

// Current time as unix seconds, the unit of every timestamp column.
long long unixNow();

} // namespace tlmhub::server
