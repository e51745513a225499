#pragma once
// Teaching labs as stored: classes and their members, assignments (a template model handed
// out, the teacher's solution and its reference result), the checks of an assignment, each
// student's copy (a model the student owns, in table models), hand-ins (frozen copies with
// their check results and grade) and comments on hand-ins. Who may do what is decided above
// the store (server/labs/LabAccess); the store only keeps the facts.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tlmhub::server {

inline constexpr const char* kClassTeacher = "teacher";
inline constexpr const char* kClassAssistant = "assistant";
inline constexpr const char* kClassStudent = "student";

struct ClassInfo {
    std::int64_t id = 0;
    std::string name;
    std::int64_t ownerId = 0;            // the teacher who created it
    std::string joinCode;                // unique among classes
    bool archived = false;               // read-only
    std::int64_t createdAt = 0;          // unix s
};

struct ClassMember {
    std::int64_t classId = 0, userId = 0;
    std::string username;
    std::string role;                    // kClassTeacher, kClassAssistant or kClassStudent
    std::int64_t joinedAt = 0;
};

// A class as one member sees it in a list: the class and the member's role in it.
struct Membership {
    ClassInfo theClass;
    std::string role;
};

struct AssignmentInfo {
    std::int64_t id = 0, classId = 0;
    std::string title;
    std::string instructions;            // Markdown as the teacher wrote it
    std::string editMode;                // "parameters" (only the listed ones) or "free"
    std::string parameters;              // JSON array text: [{"name", "min"?, "max"?}, ...]
    std::int64_t opensAt = 0, dueAt = 0; // unix s; dueAt 0: no deadline
    std::int64_t templateVersion = 1;    // +1 at each new template
    bool hasSolution = false;            // a solution and its reference result are stored
    std::int64_t createdAt = 0, updatedAt = 0;
};

struct AssignmentCheck {
    std::int64_t position = 0;           // order within the assignment, 0-based
    std::string name;
    bool pretest = false;                // the student may run it before handing in
    double points = 0;
    std::string definition;              // JSON object text, read by server/labs/LabChecks
};

struct StudentCopy {
    std::int64_t assignmentId = 0, studentId = 0;
    std::int64_t modelId = 0;            // the student's model (table models)
    std::int64_t templateVersion = 0;    // the template it was made from or last reset to
    std::int64_t createdAt = 0;
};

struct HandIn {
    std::int64_t id = 0, assignmentId = 0, studentId = 0;
    std::string studentName;
    std::int64_t attempt = 0;            // 1, 2, ... per student and assignment
    std::string hmf;                     // the copy as frozen at hand-in (not in lists)
    std::optional<std::int64_t> jobId;   // the student's latest run of the copy at hand-in
    std::int64_t handedInAt = 0;
    bool late = false;
    double score = 0, maxScore = 0;      // from the checks
    std::string checkResults;            // JSON array text
    std::optional<double> grade;         // set by a teacher; overrides the score in the gradebook
    std::optional<std::int64_t> gradedBy;
};

struct HandInComment {
    std::int64_t id = 0, handInId = 0, authorId = 0;
    std::string authorName;
    std::string text;
    std::int64_t createdAt = 0;
};

class LabStore {
public:
    virtual ~LabStore() = default;

    // ---- classes
    // A new class with `ownerId` as its teacher member, in one transaction. Nullopt when the
    // owner does not exist or the join code is taken.
    virtual std::optional<std::int64_t> createClass(std::int64_t ownerId, const std::string& name,
                                                    const std::string& joinCode) = 0;
    virtual std::optional<ClassInfo> classInfo(std::int64_t id) = 0;
    virtual std::optional<ClassInfo> classByJoinCode(const std::string& code) = 0;
    virtual std::vector<ClassInfo> listClasses() = 0;                        // by id
    virtual std::vector<Membership> classesOf(std::int64_t userId) = 0;      // by class id
    virtual bool setArchived(std::int64_t classId, bool archived) = 0;
    virtual bool renameClass(std::int64_t classId, const std::string& name) = 0;
    // Deletes the class with everything in it (assignments, copies' links, hand-ins, comments;
    // the copies' models stay with their owners).
    virtual bool removeClass(std::int64_t classId) = 0;

    // ---- members
    // Adds the user with `role`, or changes the role of a member. False when the class or the
    // user does not exist.
    virtual bool setMember(std::int64_t classId, std::int64_t userId, const std::string& role) = 0;
    virtual bool removeMember(std::int64_t classId, std::int64_t userId) = 0;
    virtual std::optional<std::string> memberRole(std::int64_t classId, std::int64_t userId) = 0;
    virtual std::vector<ClassMember> members(std::int64_t classId) = 0;      // by user name
    // Whether `staffId` is teacher or assistant of a class in which `studentId` is a student
    // and which holds the assignment whose copy `modelId` is (lab supervision of one copy).
    virtual bool supervisesCopy(std::int64_t staffId, std::int64_t modelId) = 0;

    // ---- assignments
    // A new assignment at template version 1; `solutionHmf` empty: none yet.
    virtual std::optional<std::int64_t> createAssignment(const AssignmentInfo& info, const std::string& templateHmf,
                                                         const std::string& solutionHmf) = 0;
    virtual std::optional<AssignmentInfo> assignment(std::int64_t id) = 0;
    virtual std::vector<AssignmentInfo> assignmentsOf(std::int64_t classId) = 0;   // by opens_at, id
    // Title, instructions, edit mode, parameters, opens_at and due_at of `info.id`.
    virtual bool updateAssignment(const AssignmentInfo& info) = 0;
    // Replaces the template and returns its new version (nullopt: no such assignment).
    virtual std::optional<std::int64_t> setTemplate(std::int64_t id, const std::string& hmf) = 0;
    virtual std::optional<std::string> templateHmf(std::int64_t id) = 0;
    // The solution with its reference result (an encodeResult blob), both or neither.
    virtual bool setSolution(std::int64_t id, const std::string& hmf, const std::string& referenceBlob) = 0;
    virtual std::optional<std::string> solutionHmf(std::int64_t id) = 0;
    virtual std::optional<std::string> referenceResult(std::int64_t id) = 0;
    virtual bool removeAssignment(std::int64_t id) = 0;

    // ---- checks
    virtual bool replaceChecks(std::int64_t assignmentId, const std::vector<AssignmentCheck>& checks) = 0;
    virtual std::vector<AssignmentCheck> checks(std::int64_t assignmentId) = 0;   // by position

    // ---- copies
    // False when the student has a copy already (one per student and assignment) or the
    // assignment, student or model does not exist.
    virtual bool createCopy(const StudentCopy& copy) = 0;
    virtual std::optional<StudentCopy> copy(std::int64_t assignmentId, std::int64_t studentId) = 0;
    virtual std::optional<StudentCopy> copyByModel(std::int64_t modelId) = 0;
    virtual std::vector<StudentCopy> copies(std::int64_t assignmentId) = 0;       // by student id
    virtual bool setCopyTemplateVersion(std::int64_t assignmentId, std::int64_t studentId, std::int64_t version) = 0;

    // ---- hand-ins
    // Stores a hand-in with the next attempt number of its student (ignoring `handIn.id` and
    // `attempt`); returns it as stored, or nullopt when the assignment or student is gone.
    virtual std::optional<HandIn> addHandIn(const HandIn& handIn) = 0;
    virtual std::optional<HandIn> handIn(std::int64_t id) = 0;                   // with hmf
    // Newest first, without hmf; `studentId` set: that student's only.
    virtual std::vector<HandIn> handIns(std::int64_t assignmentId, std::optional<std::int64_t> studentId) = 0;
    virtual bool setGrade(std::int64_t handInId, std::optional<double> grade, std::int64_t gradedBy) = 0;

    // ---- comments
    virtual std::optional<std::int64_t> addComment(std::int64_t handInId, std::int64_t authorId,
                                                   const std::string& text) = 0;
    virtual std::vector<HandInComment> comments(std::int64_t handInId) = 0;       // oldest first
};

} // namespace tlmhub::server
