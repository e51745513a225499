#pragma once
// What the remote commands other than login share: the client built from the stored
// credentials, model upload, waiting for a job or study with a progress display, and
// writing what the server sent to a file.
#include "cli/remote/ApiClient.h"

#include <string>

namespace tlmhub::cli::remote {

// A client for the server and token of loadCredentials(); throws when there are none.
ApiClient connectWithCredentials();

// The model a command names: a stored model's id (digits that name no file; 404 when the
// caller has no such model), or an .hmf file, uploaded as a model named after the file (its
// stem). Returns the model id.
long long modelId(ApiClient& api, const std::string& model);

// Polls `path` (a JobInfo or StudyInfo) until its state is final (done, failed, cancelled,
// interrupted), showing the progress as `label`; returns the last answer.
nlohmann::json waitUntilFinished(ApiClient& api, const std::string& path, const std::string& label);

// Writes `bytes` to `path` exactly; throws naming the path on failure.
void writeFile(const std::string& path, const std::string& bytes);

// `bytes` to stdout exactly (a CSV when no --csv file is given).
void writeStandardOutput(const std::string& bytes);

} // namespace tlmhub::cli::remote
