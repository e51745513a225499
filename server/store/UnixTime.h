#pragma once
namespace tlmhub::server {

// Current time as unix seconds, the unit of every timestamp column.
long long unixNow();
// The same in milliseconds: the job queue's leases and the nodes' heartbeats on SQLite (one
// machine, so every node agrees on this clock).
long long unixNowMillis();

} // namespace tlmhub::server
