#pragma once
// Whether models may touch the host's files: data tables, script files, loggers and external
// subsystems. The command-line tool allows it (the user runs their own files). The server
// forbids it, since a model uploaded by one user must not read or overwrite the host's files.
namespace tlmhub {

void setModelFileAccess(bool allowed);
bool modelFileAccessAllowed();

} // namespace tlmhub
