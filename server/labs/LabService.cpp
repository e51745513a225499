#include "server/labs/LabService.h"

#include "server/auth/Sodium.h"
#include "server/jobs/JobRunner.h"
#include "server/jobs/PreparedJob.h"
#include "server/labs/Gradebook.h"
#include "server/labs/ParameterLock.h"
#include "server/store/ModelName.h"
#include "server/store/ResultBlob.h"
#include "server/store/UnixTime.h"

#include <sodium.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <thread>

namespace tlmhub::server {

namespace {

using Clock = std::chrono::steady_clock;

// Runs `hmf` as a job would (its settings, the job limits) on this thread and hands the
// finished run's results to `use`.
template <typename Use>
std::optional<LabError> runModel(const std::string& hmf, const JobLimits& limits, double wallSeconds, Use&& use)
{
    JobRequest request;
    request.hmf = hmf;
    PreparedJob prepared;
    PrepareError prepareError;
    if (!prepareJob(request, limits, prepared, prepareError))
        return LabError{prepareError.code, prepareError.message};
    Simulation& simulation = *prepared.simulation;
    const double seconds = std::min(limits.maxWallSeconds, wallSeconds);
    const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    bool wallTimeExceeded = false;
    RunOptions options;
    options.threads = 1;
    options.progressInterval = JobRunner::kProgressInterval;
    options.progress = [&](std::size_t, std::size_t) {
        if (!wallTimeExceeded && Clock::now() > deadline) {
            wallTimeExceeded = true;
            simulation.requestStop();
        }
    };
    // A model that ends its own run (SignalStopSimulation) ran as designed: it is checked.
    if (const Status ran = simulation.run(options); !ran && ran.code() != StatusCode::SimulationEnded)
        return LabError{wallTimeExceeded ? "limit_exceeded" : "simulation_failed",
                        wallTimeExceeded ? wallTimeLimitMessage(seconds) : ran.message()};
    use(simulation.results());
    return std::nullopt;
}

// A model name for a student's copy: the assignment's title, cut to what names allow.
std::string copyName(const std::string& title)
{
    std::string name = title.substr(0, 100);
    return modelNameProblem(name).empty() ? name : "Assignment copy";
}

nlohmann::json userRef(std::int64_t id, const std::string& name) { return {{"id", id}, {"username", name}}; }

// The variables the checks (all, or the pretests) read, each once.
std::vector<std::string> checkedVariables(const std::vector<AssignmentCheck>& checks, bool pretestsOnly)
{
    std::vector<std::string> variables;
    for (const AssignmentCheck& check : checks) {
        if (pretestsOnly && !check.pretest) continue;
        const nlohmann::json definition = nlohmann::json::parse(check.definition, nullptr, false);
        if (!definition.is_object() || !definition.contains("variable") || !definition["variable"].is_string()) continue;
        const std::string name = definition["variable"].get<std::string>();
        if (std::find(variables.begin(), variables.end(), name) == variables.end()) variables.push_back(name);
    }
    return variables;
}

} // namespace

nlohmann::json Judgement::toJson() const
{
    return {{"checks", outcomesJson(outcomes)}, {"score", score}, {"max_score", maxScore}};
}

LabService::LabService(LabStore& labs, ModelStore& models, JobStore& jobs, ResultStore& results, const JobLimits& limits)
    : mLabs(labs), mModels(models), mJobs(jobs), mResults(results), mLimits(limits)
{
}

std::string LabService::newJoinCode()
{
    // 31 letters and digits without 0/O, 1/I/L: read aloud and typed without mistakes.
    static constexpr char kAlphabet[] = "23456789ABCDEFGHJKMNPQRSTUVWXYZ";
    ensureSodium();
    std::string code(12, ' ');
    for (char& c : code) c = kAlphabet[randombytes_uniform(sizeof kAlphabet - 1)];
    return code;
}

std::optional<std::int64_t> LabService::createClass(const User& teacher, const std::string& name)
{
    // A taken code (about one in 2^59 per class) just means another draw.
    for (int attempt = 0; attempt < 4; ++attempt)
        if (auto id = mLabs.createClass(teacher.id, name, newJoinCode())) return id;
    return std::nullopt;
}

std::optional<LabError> LabService::setSolution(std::int64_t assignmentId, const std::string& solutionHmf)
{
    std::string blob;
    if (auto failed = runModel(solutionHmf, mLimits, kCheckWallSeconds, [&](const ResultView& view) { blob = encodeResult(view); }))
        return LabError{failed->code, "the solution does not run: " + failed->message};
    if (!mLabs.setSolution(assignmentId, solutionHmf, blob)) return LabError{"not_found", "no such assignment"};
    return std::nullopt;
}

std::optional<std::int64_t> LabService::publishTemplate(const AssignmentInfo& assignment, const std::string& hmf)
{
    const auto previous = mLabs.templateHmf(assignment.id);
    const auto version = mLabs.setTemplate(assignment.id, hmf);
    if (!version || !previous) return version;
    for (const StudentCopy& copy : mLabs.copies(assignment.id)) {
        // A copy the student has not changed yet follows; a changed one is only told (outdated).
        if (copy.templateVersion != assignment.templateVersion || mModels.hmf(copy.modelId) != previous) continue;
        mModels.update(copy.modelId, std::nullopt, hmf);
        mLabs.setCopyTemplateVersion(assignment.id, copy.studentId, *version);
    }
    return version;
}

std::vector<AssignmentWarning> LabService::warnings(const AssignmentInfo& assignment)
{
    std::vector<AssignmentWarning> found;
    const auto add = [&](std::vector<AssignmentWarning> more) {
        found.insert(found.end(), std::make_move_iterator(more.begin()), std::make_move_iterator(more.end()));
    };
    std::string why;
    const auto lock = ParameterLock::parse(nlohmann::json::parse(assignment.parameters, nullptr, false), why);
    if (assignment.editMode == "parameters" && lock) {
        if (const auto hmf = mLabs.templateHmf(assignment.id)) add(parameterWarnings(*lock, *hmf, "template", mLimits.model));
        if (const auto hmf = assignment.hasSolution ? mLabs.solutionHmf(assignment.id) : std::nullopt)
            add(parameterWarnings(*lock, *hmf, "solution", mLimits.model));
    }
    const std::vector<AssignmentCheck> checks = mLabs.checks(assignment.id);
    const auto blob = assignment.hasSolution && !checks.empty() ? mLabs.referenceResult(assignment.id) : std::nullopt;
    if (const auto reference = blob ? decodeResult(*blob, checkedVariables(checks, false)) : std::nullopt)
        add(solutionCheckWarnings(checks, *reference));
    return found;
}

std::optional<LabError> LabService::setChecks(const AssignmentInfo& assignment, const std::vector<AssignmentCheck>& checks)
{
    const auto reference = assignment.hasSolution ? mLabs.referenceResult(assignment.id) : std::nullopt;
    const auto table = reference ? decodeResult(*reference) : std::nullopt;
    std::vector<AssignmentCheck> stored;
    for (std::size_t i = 0; i < checks.size(); ++i) {
        const std::string where = "checks[" + std::to_string(i) + "]";
        std::string error;
        const auto definition = parseCheckDefinition(nlohmann::json::parse(checks[i].definition, nullptr, false), error);
        if (!definition) return LabError{"bad_request", where + "." + error};
        if (definition->kind == "curve" && !table)
            return LabError{"bad_request", where + ": a curve check needs the teacher's solution (solution_model_id)"};
        if (table && !table->hasColumn(definition->variable))
            return LabError{"bad_request", where + ": the solution does not log " + definition->variable};
        AssignmentCheck check = checks[i];
        check.position = static_cast<std::int64_t>(i);
        check.definition = checkDefinitionJson(*definition).dump();
        stored.push_back(std::move(check));
    }
    if (!mLabs.replaceChecks(assignment.id, stored)) return LabError{"not_found", "no such assignment"};
    return std::nullopt;
}

std::optional<StudentCopy> LabService::openCopy(const AssignmentInfo& assignment, const User& student, bool& created,
                                                LabError& error)
{
    created = false;
    if (auto copy = mLabs.copy(assignment.id, student.id)) return copy;
    const auto hmf = mLabs.templateHmf(assignment.id);
    if (!hmf) {
        error = {"not_found", "no such assignment"};
        return std::nullopt;
    }
    const auto modelId = mModels.create(student.id, copyName(assignment.title), *hmf, false);
    if (!modelId) {
        error = {"not_found", "no such user"};
        return std::nullopt;
    }
    const StudentCopy copy{assignment.id, student.id, *modelId, assignment.templateVersion, unixNow()};
    if (!mLabs.createCopy(copy)) {
        // Opened twice at once: the other call's copy stands.
        mModels.remove(*modelId);
        return mLabs.copy(assignment.id, student.id);
    }
    created = true;
    return mLabs.copy(assignment.id, student.id);
}

std::optional<StudentCopy> LabService::resetCopy(const AssignmentInfo& assignment, const User& student, LabError& error)
{
    const auto copy = mLabs.copy(assignment.id, student.id);
    const auto hmf = mLabs.templateHmf(assignment.id);
    if (!copy || !hmf) {
        error = {"conflict", "open the assignment first"};
        return std::nullopt;
    }
    mModels.update(copy->modelId, std::nullopt, *hmf);
    mLabs.setCopyTemplateVersion(assignment.id, student.id, assignment.templateVersion);
    return mLabs.copy(assignment.id, student.id);
}

nlohmann::json LabService::copyJson(const AssignmentInfo& assignment, const StudentCopy& copy)
{
    return {{"model_id", copy.modelId},
            {"template_version", copy.templateVersion},
            {"outdated", copy.templateVersion < assignment.templateVersion}};
}

std::optional<Judgement> LabService::judge(const AssignmentInfo& assignment, const std::string& hmf, bool pretestsOnly,
                                           LabError& error)
{
    const std::vector<AssignmentCheck> checks = mLabs.checks(assignment.id);
    // Only the variables the checks read are kept of the run and decoded of the reference: a
    // class hands in at once, and the rest of a result would be copied for nothing.
    const std::vector<std::string> variables = checkedVariables(checks, pretestsOnly);
    ResultTable run;
    if (auto failed = runModel(hmf, mLimits, kCheckWallSeconds, [&](const ResultView& view) {
            run.time.assign(view.time().begin(), view.time().end());
            for (const std::string& name : variables)
                if (auto values = view.data(name)) run.columns.push_back({name, "", std::move(*values)});
        })) {
        error = {failed->code, "the model does not run: " + failed->message};
        return std::nullopt;
    }
    return evaluate(assignment, checks, run, variables, pretestsOnly);
}

std::optional<JobInfo> LabService::waitForRun(std::int64_t jobId, std::chrono::milliseconds wait)
{
    const auto deadline = Clock::now() + wait;
    // Short first looks (a small model ends in milliseconds), then at most 5 a second.
    std::chrono::milliseconds pause{5};
    for (;;) {
        std::optional<JobInfo> info = mJobs.info(jobId);
        const auto now = Clock::now();
        if (!info || isFinished(info->state) || now >= deadline) return info;
        std::this_thread::sleep_for(std::min<Clock::duration>(pause, deadline - now));
        pause = std::min(pause * 2, std::chrono::milliseconds(200));
    }
}

std::optional<Judgement> LabService::judgeRun(const AssignmentInfo& assignment, const JobInfo& run, bool pretestsOnly,
                                              LabError& error)
{
    if (run.state != JobState::Done) {
        const std::string why = run.error.empty() ? std::string("its run ended ") + jobStateName(run.state) : run.error;
        error = {"simulation_failed", "the model does not run: " + why};
        return std::nullopt;
    }
    const std::vector<AssignmentCheck> checks = mLabs.checks(assignment.id);
    const std::vector<std::string> variables = checkedVariables(checks, pretestsOnly);
    const auto blob = mResults.blob(run.id);
    const auto table = blob ? decodeResult(*blob, variables) : std::nullopt;
    if (!table) {
        error = {"conflict", "the results of run " + std::to_string(run.id) + " are no longer kept: run the pretests again"};
        return std::nullopt;
    }
    return evaluate(assignment, checks, *table, variables, pretestsOnly);
}

Judgement LabService::evaluate(const AssignmentInfo& assignment, const std::vector<AssignmentCheck>& checks,
                               const ResultTable& run, const std::vector<std::string>& variables, bool pretestsOnly)
{
    const auto blob = assignment.hasSolution && !variables.empty() ? mLabs.referenceResult(assignment.id) : std::nullopt;
    const auto reference = blob ? decodeResult(*blob, variables) : std::nullopt;
    Judgement judgement;
    judgement.outcomes = evaluateChecks(checks, run, reference ? &*reference : nullptr, pretestsOnly);
    for (const CheckOutcome& outcome : judgement.outcomes) {
        judgement.score += outcome.awarded;
        judgement.maxScore += outcome.points;
    }
    return judgement;
}

std::optional<HandIn> LabService::handIn(const AssignmentInfo& assignment, const User& student,
                                         std::int64_t receivedAt, LabError& error)
{
    const auto copy = mLabs.copy(assignment.id, student.id);
    if (!copy) {
        error = {"conflict", "open the assignment first"};
        return std::nullopt;
    }
    const std::int64_t now = receivedAt;
    const bool late = assignment.dueAt != 0 && now > assignment.dueAt;
    if (late && !mLabs.handIns(assignment.id, student.id).empty()) {
        error = {"deadline_passed", "the deadline has passed: your earlier hand-in stands"};
        return std::nullopt;
    }
    const auto hmf = mModels.hmf(copy->modelId);
    if (!hmf) {
        error = {"conflict", "your copy is gone"};
        return std::nullopt;
    }
    const auto judgement = judge(assignment, *hmf, false, error);
    if (!judgement) return std::nullopt;
    HandIn handIn;
    handIn.assignmentId = assignment.id;
    handIn.studentId = student.id;
    handIn.hmf = *hmf;
    if (const auto run = latestRun(student.id, copy->modelId)) handIn.jobId = run->id;
    handIn.handedInAt = now;
    handIn.late = late;
    handIn.score = judgement->score;
    handIn.maxScore = judgement->maxScore;
    handIn.checkResults = outcomesJson(judgement->outcomes).dump();
    auto stored = mLabs.addHandIn(handIn);
    if (!stored) error = {"not_found", "no such assignment"};
    return stored;
}

std::optional<JobInfo> LabService::latestRun(std::int64_t studentId, std::int64_t modelId, bool doneOnly)
{
    for (JobInfo& job : mJobs.listForOwner(studentId))   // newest first
        if (job.modelId == modelId && (!doneOnly || job.state == JobState::Done)) return std::move(job);
    return std::nullopt;
}

std::string LabService::studentStatus(const AssignmentInfo& assignment, std::int64_t studentId)
{
    const auto handIns = mLabs.handIns(assignment.id, studentId);
    if (!handIns.empty()) return handIns.front().late ? "late" : "handed_in";
    const auto copy = mLabs.copy(assignment.id, studentId);
    if (!copy) return "not_opened";
    return latestRun(studentId, copy->modelId) ? "ran" : "working";
}

nlohmann::json LabService::dashboard(const AssignmentInfo& assignment)
{
    nlohmann::json rows = nlohmann::json::array();
    for (const ClassMember& member : mLabs.members(assignment.classId)) {
        if (member.role != kClassStudent) continue;
        nlohmann::json row = {{"student", userRef(member.userId, member.username)},
                              {"status", studentStatus(assignment, member.userId)},
                              {"copy_model_id", nullptr}, {"last_run_at", nullptr}, {"job_id", nullptr},
                              {"handins", 0}, {"handed_in_at", nullptr}, {"late", false},
                              {"score", nullptr}, {"max_score", nullptr}, {"grade", nullptr}, {"handin_id", nullptr}};
        if (const auto copy = mLabs.copy(assignment.id, member.userId)) {
            row["copy_model_id"] = copy->modelId;
            if (const auto run = latestRun(member.userId, copy->modelId)) {
                row["job_id"] = run->id;
                row["last_run_at"] = run->createdAt;
            }
        }
        const auto handIns = mLabs.handIns(assignment.id, member.userId);
        row["handins"] = handIns.size();
        if (!handIns.empty()) {
            const HandIn& latest = handIns.front();
            row["handin_id"] = latest.id;
            row["handed_in_at"] = latest.handedInAt;
            row["late"] = latest.late;
            row["score"] = latest.score;
            row["max_score"] = latest.maxScore;
            if (latest.grade) row["grade"] = *latest.grade;
        }
        rows.push_back(std::move(row));
    }
    return {{"students", rows}};
}

nlohmann::json LabService::overlay(const AssignmentInfo& assignment, const std::string& variable, std::size_t points)
{
    nlohmann::json series = nlohmann::json::array();
    points = std::max<std::size_t>(points, 2);
    for (const ClassMember& member : mLabs.members(assignment.classId)) {
        if (member.role != kClassStudent) continue;
        const auto copy = mLabs.copy(assignment.id, member.userId);
        if (!copy) continue;
        // The newest run that finished: a running one has no stored result yet.
        const auto run = latestRun(member.userId, copy->modelId, true);
        if (!run) continue;
        const auto table = mResults.result(run->id, {variable});
        if (!table || !table->hasColumn(variable)) continue;
        const std::vector<double>& values = table->column(variable)->data;
        const std::vector<double>& time = table->time;
        const std::size_t n = std::min(time.size(), values.size());
        // Every stride-th sample and the last one: at most `points` in all.
        const std::size_t stride = n <= points ? 1 : (n - 1 + points - 2) / (points - 1);
        nlohmann::json t = nlohmann::json::array(), v = nlohmann::json::array();
        for (std::size_t i = 0; i < n; i += stride) {
            t.push_back(time[i]);
            v.push_back(values[i]);
        }
        if (n > 0 && (n - 1) % stride != 0) {   // always end at the last sample
            t.push_back(time[n - 1]);
            v.push_back(values[n - 1]);
        }
        series.push_back({{"student", userRef(member.userId, member.username)}, {"job_id", run->id},
                          {"time", std::move(t)}, {"values", std::move(v)}});
    }
    return {{"variable", variable}, {"series", series}};
}

struct LabService::GradebookData {
    std::vector<AssignmentInfo> assignments;
    std::vector<ClassMember> students;
    std::vector<GradebookRow> rows;
};

LabService::GradebookData LabService::gradebook(std::int64_t classId)
{
    GradebookData data;
    data.assignments = mLabs.assignmentsOf(classId);
    for (ClassMember& member : mLabs.members(classId)) {
        if (member.role != kClassStudent) continue;
        GradebookRow row{member.username, {}};
        for (const AssignmentInfo& assignment : data.assignments) {
            const auto handIns = mLabs.handIns(assignment.id, member.userId);
            GradebookCell cell;
            if (!handIns.empty()) {
                cell.points = handIns.front().grade.value_or(handIns.front().score);
                cell.late = handIns.front().late;
            }
            row.cells.push_back(cell);
        }
        data.rows.push_back(std::move(row));
        data.students.push_back(std::move(member));
    }
    return data;
}

std::string LabService::gradebookCsv(std::int64_t classId)
{
    GradebookData data = gradebook(classId);
    std::vector<std::string> titles;
    for (const AssignmentInfo& a : data.assignments) titles.push_back(a.title);
    return server::gradebookCsv(titles, data.rows);
}

nlohmann::json LabService::gradebookJson(std::int64_t classId)
{
    GradebookData data = gradebook(classId);
    nlohmann::json assignments = nlohmann::json::array(), students = nlohmann::json::array();
    for (const AssignmentInfo& a : data.assignments) assignments.push_back({{"id", a.id}, {"title", a.title}});
    for (std::size_t i = 0; i < data.rows.size(); ++i) {
        nlohmann::json cells = nlohmann::json::array();
        for (const GradebookCell& cell : data.rows[i].cells)
            cells.push_back({{"points", cell.points ? nlohmann::json(*cell.points) : nlohmann::json(nullptr)},
                             {"late", cell.late}});
        students.push_back({{"student", userRef(data.students[i].userId, data.students[i].username)}, {"cells", cells}});
    }
    return {{"assignments", assignments}, {"students", students}};
}

nlohmann::json LabService::classJson(const ClassInfo& info, const std::string& ownerName, const std::string& role)
{
    nlohmann::json out = {{"id", info.id},     {"name", info.name},         {"owner", userRef(info.ownerId, ownerName)},
                          {"archived", info.archived}, {"created_at", info.createdAt}, {"role", role}};
    // Only staff hand the code out.
    if (role == kClassTeacher || role == kClassAssistant) out["join_code"] = info.joinCode;
    return out;
}

nlohmann::json LabService::assignmentJson(const AssignmentInfo& a)
{
    return {{"id", a.id},
            {"class_id", a.classId},
            {"title", a.title},
            {"instructions", a.instructions},
            {"edit_mode", a.editMode},
            {"parameters", nlohmann::json::parse(a.parameters, nullptr, false)},
            {"opens_at", a.opensAt},
            {"due_at", a.dueAt},
            {"template_version", a.templateVersion},
            {"has_solution", a.hasSolution},
            {"created_at", a.createdAt},
            {"updated_at", a.updatedAt}};
}

nlohmann::json LabService::handInJson(const HandIn& h, bool staff)
{
    const nlohmann::json checks = nlohmann::json::parse(h.checkResults, nullptr, false);
    return {{"id", h.id},
            {"assignment_id", h.assignmentId},
            {"student", userRef(h.studentId, h.studentName)},
            {"attempt", h.attempt},
            {"handed_in_at", h.handedInAt},
            {"late", h.late},
            {"score", h.score},
            {"max_score", h.maxScore},
            {"grade", h.grade ? nlohmann::json(*h.grade) : nlohmann::json(nullptr)},
            {"job_id", h.jobId ? nlohmann::json(*h.jobId) : nlohmann::json(nullptr)},
            {"checks", staff ? checks : outcomesForStudent(checks)}};
}

} // namespace tlmhub::server
