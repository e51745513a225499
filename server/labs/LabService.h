#pragma once
// The lab operations that span several stores or run a model: join codes and imported
// accounts, a student's copy (made from the template, following new templates while it is
// unchanged), the teacher's reference run, judging a copy by the checks (pretest and
// hand-in), and the teacher's views over all students (dashboard, overlay plot, gradebook).
// Access is the caller's business (LabAccess); these functions trust their arguments.
#include "server/auth/User.h"
#include "server/jobs/Job.h"
#include "server/labs/AssignmentWarnings.h"
#include "server/labs/LabChecks.h"
#include "server/store/JobStore.h"
#include "server/store/LabStore.h"
#include "server/store/ModelStore.h"
#include "server/store/ResultStore.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

// A refusal: the protocol's error code and a message (the routes add the HTTP status).
struct LabError {
    std::string code;
    std::string message;
};

struct Judgement {
    std::vector<CheckOutcome> outcomes;
    double score = 0, maxScore = 0;
    nlohmann::json toJson() const;
};

class LabService {
public:
    LabService(LabStore& labs, ModelStore& models, JobStore& jobs, ResultStore& results, const JobLimits& limits);

    LabStore& store() { return mLabs; }

    // 12 characters of an alphabet without look-alikes (about 59 bits).
    static std::string newJoinCode();
    std::optional<std::int64_t> createClass(const User& teacher, const std::string& name);

    // Runs `solutionHmf` and keeps it with its result as the assignment's reference.
    std::optional<LabError> setSolution(std::int64_t assignmentId, const std::string& solutionHmf);
    // A new template version; copies still equal to the template they came from get it too.
    std::optional<std::int64_t> publishTemplate(const AssignmentInfo& assignment, const std::string& hmf);
    // What the teacher is warned of (AssignmentWarnings.h): with edit mode "parameters", the
    // template's and the solution's listed parameters against their bounds; the checks against
    // the solution's reference run, stored when the solution was set, so nothing runs here.
    std::vector<AssignmentWarning> warnings(const AssignmentInfo& assignment);
    // Checks the definitions against the reference run and stores them.
    std::optional<LabError> setChecks(const AssignmentInfo& assignment, const std::vector<AssignmentCheck>& checks);

    // The student's copy, made from the template on first call (`created` then true).
    std::optional<StudentCopy> openCopy(const AssignmentInfo& assignment, const User& student, bool& created,
                                        LabError& error);
    // The copy gets the current template.
    std::optional<StudentCopy> resetCopy(const AssignmentInfo& assignment, const User& student, LabError& error);
    nlohmann::json copyJson(const AssignmentInfo& assignment, const StudentCopy& copy);

    // Runs `hmf` on this thread (within the job limits, at most kCheckWallSeconds) and judges
    // it by the assignment's checks (or its pretests only).
    std::optional<Judgement> judge(const AssignmentInfo& assignment, const std::string& hmf, bool pretestsOnly,
                                   LabError& error);
    // A check run that went through the job queue (a pretest): its info once it has ended, or
    // as it is when `wait` has passed first (polling the store: the run may be on another node).
    std::optional<JobInfo> waitForRun(std::int64_t jobId, std::chrono::milliseconds wait);
    // Judges the stored result of an ended run by the assignment's checks (or its pretests
    // only); a run that did not end done is an error saying why.
    std::optional<Judgement> judgeRun(const AssignmentInfo& assignment, const JobInfo& run, bool pretestsOnly,
                                      LabError& error);
    // Freezes the student's copy with its latest run, judges it and stores the hand-in.
    // `receivedAt` (unix seconds): when the request had been read whole; the hand-in's time and
    // what the deadline is judged by, however long it waited for a check thread.
    std::optional<HandIn> handIn(const AssignmentInfo& assignment, const User& student, std::int64_t receivedAt,
                                 LabError& error);

    // not_opened, working, ran, handed_in or late.
    std::string studentStatus(const AssignmentInfo& assignment, std::int64_t studentId);
    nlohmann::json dashboard(const AssignmentInfo& assignment);
    // Each student's latest finished run of their copy: `variable` at most `points` samples.
    nlohmann::json overlay(const AssignmentInfo& assignment, const std::string& variable, std::size_t points);
    // One row per student of the class, one column per assignment.
    std::string gradebookCsv(std::int64_t classId);
    nlohmann::json gradebookJson(std::int64_t classId);

    static nlohmann::json classJson(const ClassInfo& info, const std::string& ownerName, const std::string& role);
    static nlohmann::json assignmentJson(const AssignmentInfo& assignment);
    // `staff`: the class's teacher or an assistant sees every check's details; a student sees
    // those of the pretests only (outcomesForStudent).
    static nlohmann::json handInJson(const HandIn& handIn, bool staff);

    static constexpr double kCheckWallSeconds = 60;

private:
    // The checks' outcomes for `run` (holding `variables`, those the checks read).
    Judgement evaluate(const AssignmentInfo& assignment, const std::vector<AssignmentCheck>& checks,
                       const ResultTable& run, const std::vector<std::string>& variables, bool pretestsOnly);
    // The student's newest job on model `modelId` (in any state, or only a finished one), if any.
    std::optional<JobInfo> latestRun(std::int64_t studentId, std::int64_t modelId, bool doneOnly = false);
    struct GradebookData;
    GradebookData gradebook(std::int64_t classId);

    LabStore& mLabs;
    ModelStore& mModels;
    JobStore& mJobs;
    ResultStore& mResults;
    const JobLimits& mLimits;
};

} // namespace tlmhub::server
