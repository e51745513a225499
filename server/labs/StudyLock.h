#pragma once
// A study of a student's copy under a parameter lock: every parameter it fixes, sweeps, samples
// or optimises must be one the assignment lets the student change, and every value it can
// take must lie within that parameter's bounds.
#include "server/labs/ParameterLock.h"
#include "server/studies/StudyRequest.h"

#include <string>

namespace tlmhub::server {

// "" when the study keeps to the lock, else the first parameter or value that does not.
std::string studyLockProblem(const StudyRequest& request, const ParameterLock& lock);

} // namespace tlmhub::server
