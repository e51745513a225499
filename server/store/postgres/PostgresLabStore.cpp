#include "server/store/UnixTime.h"
#include "server/store/postgres/PostgresStores.h"

#include <cstdio>

namespace tlmhub::server {

namespace {

#define TLMHUB_CLASS_COLUMNS "c.id, c.name, c.owner_id, c.join_code, c.archived, c.created_at"
constexpr PgStatement kCreateClass{"labs_create_class",
                                   "INSERT INTO classes(name, owner_id, join_code, created_at) VALUES($1, $2, $3, $4)"
                                   " ON CONFLICT (join_code) DO NOTHING RETURNING id"};
constexpr PgStatement kClassById{"labs_class_by_id", "SELECT " TLMHUB_CLASS_COLUMNS " FROM classes c WHERE c.id = $1"};
constexpr PgStatement kClassByCode{"labs_class_by_code",
                                   "SELECT " TLMHUB_CLASS_COLUMNS " FROM classes c WHERE c.join_code = $1"};
constexpr PgStatement kListClasses{"labs_list_classes", "SELECT " TLMHUB_CLASS_COLUMNS " FROM classes c ORDER BY c.id"};
constexpr PgStatement kClassesOf{"labs_classes_of",
                                 "SELECT " TLMHUB_CLASS_COLUMNS ", m.role FROM class_members m"
                                 " JOIN classes c ON c.id = m.class_id WHERE m.user_id = $1 ORDER BY c.id"};
#undef TLMHUB_CLASS_COLUMNS
constexpr PgStatement kSetArchived{"labs_set_archived", "UPDATE classes SET archived = $1 WHERE id = $2"};
constexpr PgStatement kRenameClass{"labs_rename_class", "UPDATE classes SET name = $1 WHERE id = $2"};
// Members, assignments, checks, copies' links, hand-ins and comments go with it (ON DELETE
// CASCADE), in the same statement.
constexpr PgStatement kRemoveClass{"labs_remove_class", "DELETE FROM classes WHERE id = $1"};

// A member keeps the time they joined when their role changes.
constexpr PgStatement kSetMember{"labs_set_member",
                                 "INSERT INTO class_members(class_id, user_id, role, joined_at) VALUES($1, $2, $3, $4)"
                                 " ON CONFLICT (class_id, user_id) DO UPDATE SET role = EXCLUDED.role"};
constexpr PgStatement kRemoveMember{"labs_remove_member",
                                    "DELETE FROM class_members WHERE class_id = $1 AND user_id = $2"};
constexpr PgStatement kMemberRole{"labs_member_role",
                                  "SELECT role FROM class_members WHERE class_id = $1 AND user_id = $2"};
// Names as bytes (COLLATE "C", SQLite's order), not in the database's locale.
constexpr PgStatement kMembers{"labs_members",
                               "SELECT m.class_id, m.user_id, u.username, m.role, m.joined_at FROM class_members m"
                               " JOIN users u ON u.id = m.user_id WHERE m.class_id = $1"
                               " ORDER BY u.username COLLATE \"C\", u.id"};
// The copy's owner must still be a student of the assignment's class: a removed student's
// copy is nobody's to supervise.
constexpr PgStatement kSupervisesCopy{"labs_supervises_copy",
                                      "SELECT 1 FROM student_copies sc"
                                      " JOIN assignments a ON a.id = sc.assignment_id"
                                      " JOIN class_members s ON s.class_id = a.class_id AND s.user_id = sc.student_id"
                                      "  AND s.role = 'student'"
                                      " JOIN class_members t ON t.class_id = a.class_id AND t.user_id = $1"
                                      "  AND t.role IN ('teacher', 'assistant')"
                                      " WHERE sc.model_id = $2"};

#define TLMHUB_ASSIGNMENT_INFO                                                                  \
    "SELECT id, class_id, title, instructions, edit_mode, parameters, opens_at, due_at,"       \
    " template_version, has_solution, created_at, updated_at FROM assignments"
constexpr PgStatement kCreateAssignment{"labs_create_assignment",
                                        "INSERT INTO assignments(class_id, title, instructions, edit_mode, parameters,"
                                        " opens_at, due_at, template_hmf, solution_hmf, created_at, updated_at)"
                                        " VALUES($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $10) RETURNING id"};
constexpr PgStatement kAssignment{"labs_assignment", TLMHUB_ASSIGNMENT_INFO " WHERE id = $1"};
constexpr PgStatement kAssignmentsOf{"labs_assignments_of",
                                     TLMHUB_ASSIGNMENT_INFO " WHERE class_id = $1 ORDER BY opens_at, id"};
#undef TLMHUB_ASSIGNMENT_INFO
constexpr PgStatement kUpdateAssignment{"labs_update_assignment",
                                        "UPDATE assignments SET title = $1, instructions = $2, edit_mode = $3,"
                                        " parameters = $4, opens_at = $5, due_at = $6, updated_at = $7 WHERE id = $8"};
// One statement: the version returned is the one this update made.
constexpr PgStatement kSetTemplate{"labs_set_template",
                                   "UPDATE assignments SET template_hmf = $1, template_version = template_version + 1,"
                                   " updated_at = $2 WHERE id = $3 RETURNING template_version"};
constexpr PgStatement kTemplateHmf{"labs_template_hmf", "SELECT template_hmf FROM assignments WHERE id = $1"};
constexpr PgStatement kSetSolution{"labs_set_solution",
                                   "UPDATE assignments SET solution_hmf = $1, reference_result = $2,"
                                   " has_solution = $3, updated_at = $4 WHERE id = $5"};
constexpr PgStatement kSolutionHmf{"labs_solution_hmf",
                                   "SELECT solution_hmf FROM assignments WHERE id = $1 AND solution_hmf IS NOT NULL"};
constexpr PgStatement kReferenceResult{"labs_reference_result",
                                       "SELECT reference_result FROM assignments WHERE id = $1"
                                       " AND reference_result IS NOT NULL"};
// Checks, copies' links, hand-ins and comments go with it (ON DELETE CASCADE).
constexpr PgStatement kRemoveAssignment{"labs_remove_assignment", "DELETE FROM assignments WHERE id = $1"};

// Also tells whether the assignment exists, and holds off another replacement until commit.
constexpr PgStatement kTouchAssignment{"labs_touch_assignment",
                                       "UPDATE assignments SET updated_at = $1 WHERE id = $2"};
constexpr PgStatement kClearChecks{"labs_clear_checks", "DELETE FROM assignment_checks WHERE assignment_id = $1"};
constexpr PgStatement kInsertCheck{"labs_insert_check",
                                   "INSERT INTO assignment_checks(assignment_id, position, name, pretest, points,"
                                   " definition) VALUES($1, $2, $3, $4, $5, $6)"};
constexpr PgStatement kChecks{"labs_checks",
                              "SELECT position, name, pretest, points, definition FROM assignment_checks"
                              " WHERE assignment_id = $1 ORDER BY position"};

#define TLMHUB_COPY "SELECT assignment_id, student_id, model_id, template_version, created_at FROM student_copies"
constexpr PgStatement kCreateCopy{"labs_create_copy",
                                  "INSERT INTO student_copies(assignment_id, student_id, model_id, template_version,"
                                  " created_at) VALUES($1, $2, $3, $4, $5)"};
constexpr PgStatement kCopy{"labs_copy", TLMHUB_COPY " WHERE assignment_id = $1 AND student_id = $2"};
constexpr PgStatement kCopyByModel{"labs_copy_by_model", TLMHUB_COPY " WHERE model_id = $1"};
constexpr PgStatement kCopies{"labs_copies", TLMHUB_COPY " WHERE assignment_id = $1 ORDER BY student_id"};
#undef TLMHUB_COPY
constexpr PgStatement kSetCopyTemplateVersion{"labs_set_copy_template_version",
                                              "UPDATE student_copies SET template_version = $1"
                                              " WHERE assignment_id = $2 AND student_id = $3"};

// Hand-ins of one assignment take turns on its row, so each reads the attempts committed
// before it (FOR NO KEY UPDATE: copies and other rows referring to the assignment go on).
constexpr PgStatement kLockAssignment{"labs_lock_assignment",
                                      "SELECT id FROM assignments WHERE id = $1 FOR NO KEY UPDATE"};
constexpr PgStatement kInsertHandIn{"labs_insert_handin",
                                    "INSERT INTO handins(assignment_id, student_id, attempt, hmf, job_id, handed_in_at,"
                                    " late, score, max_score, check_results, grade, graded_by)"
                                    " VALUES($1, $2, (SELECT COALESCE(MAX(attempt), 0) + 1 FROM handins"
                                    "  WHERE assignment_id = $1 AND student_id = $2),"
                                    " $3, $4, $5, $6, $7, $8, $9, $10, $11) RETURNING id"};
// Lists leave the frozen text out ('' in its place): it can be large and lists do not show it.
#define TLMHUB_HANDIN(hmf)                                                                      \
    "SELECT h.id, h.assignment_id, h.student_id, u.username, h.attempt, " hmf ", h.job_id,"   \
    " h.handed_in_at, h.late, h.score, h.max_score, h.check_results, h.grade, h.graded_by"     \
    " FROM handins h JOIN users u ON u.id = h.student_id"
constexpr PgStatement kHandIn{"labs_handin", TLMHUB_HANDIN("h.hmf") " WHERE h.id = $1"};
constexpr PgStatement kHandInsOfAssignment{"labs_handins_of_assignment",
                                           TLMHUB_HANDIN("''") " WHERE h.assignment_id = $1 ORDER BY h.id DESC"};
constexpr PgStatement kHandInsOfStudent{"labs_handins_of_student",
                                        TLMHUB_HANDIN("''") " WHERE h.assignment_id = $1 AND h.student_id = $2"
                                                            " ORDER BY h.id DESC"};
#undef TLMHUB_HANDIN
constexpr PgStatement kSetGrade{"labs_set_grade", "UPDATE handins SET grade = $1, graded_by = $2 WHERE id = $3"};

constexpr PgStatement kAddComment{"labs_add_comment",
                                  "INSERT INTO handin_comments(handin_id, author_id, text, created_at)"
                                  " VALUES($1, $2, $3, $4) RETURNING id"};
constexpr PgStatement kComments{"labs_comments",
                                "SELECT hc.id, hc.handin_id, hc.author_id, u.username, hc.text, hc.created_at"
                                " FROM handin_comments hc JOIN users u ON u.id = hc.author_id"
                                " WHERE hc.handin_id = $1 ORDER BY hc.id"};

// The text of an optional parameter (NULL when absent); doubles with all 17 digits, so the
// stored value is the one given.
std::optional<std::string> textOf(std::optional<std::int64_t> value)
{
    return value ? std::optional(std::to_string(*value)) : std::nullopt;
}

std::optional<std::string> textOf(std::optional<double> value)
{
    if (!value) return std::nullopt;
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", *value);
    return std::string(text);
}

ClassInfo readClass(const pqxx::row& row)
{
    ClassInfo c;
    c.id = row[0].as<std::int64_t>();
    c.name = row[1].as<std::string>();
    c.ownerId = nullable<std::int64_t>(row[2]).value_or(0);   // owner deleted
    c.joinCode = row[3].as<std::string>();
    c.archived = row[4].as<bool>();
    c.createdAt = row[5].as<std::int64_t>();
    return c;
}

AssignmentInfo readAssignment(const pqxx::row& row)
{
    AssignmentInfo a;
    a.id = row[0].as<std::int64_t>();
    a.classId = row[1].as<std::int64_t>();
    a.title = row[2].as<std::string>();
    a.instructions = row[3].as<std::string>();
    a.editMode = row[4].as<std::string>();
    a.parameters = row[5].as<std::string>();
    a.opensAt = row[6].as<std::int64_t>();
    a.dueAt = row[7].as<std::int64_t>();
    a.templateVersion = row[8].as<std::int64_t>();
    a.hasSolution = row[9].as<bool>();
    a.createdAt = row[10].as<std::int64_t>();
    a.updatedAt = row[11].as<std::int64_t>();
    return a;
}

StudentCopy readCopy(const pqxx::row& row)
{
    return StudentCopy{row[0].as<std::int64_t>(), row[1].as<std::int64_t>(), row[2].as<std::int64_t>(),
                       row[3].as<std::int64_t>(), row[4].as<std::int64_t>()};
}

HandIn readHandIn(const pqxx::row& row)
{
    HandIn h;
    h.id = row[0].as<std::int64_t>();
    h.assignmentId = row[1].as<std::int64_t>();
    h.studentId = row[2].as<std::int64_t>();
    h.studentName = row[3].as<std::string>();
    h.attempt = row[4].as<std::int64_t>();
    h.hmf = row[5].as<std::string>();
    h.jobId = nullable<std::int64_t>(row[6]);
    h.handedInAt = row[7].as<std::int64_t>();
    h.late = row[8].as<bool>();
    h.score = row[9].as<double>();
    h.maxScore = row[10].as<double>();
    h.checkResults = row[11].as<std::string>();
    h.grade = nullable<double>(row[12]);
    h.gradedBy = nullable<std::int64_t>(row[13]);
    return h;
}

} // namespace

// ---- classes

std::optional<std::int64_t> PostgresLabStore::createClass(std::int64_t ownerId, const std::string& name,
                                                          const std::string& joinCode)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) -> std::optional<std::int64_t> {
        const auto now = static_cast<std::int64_t>(unixNow());
        pqxx::work tx(c.raw());
        std::int64_t id = 0;
        try {
            const auto r = c.exec(tx, kCreateClass, name, ownerId, joinCode, now);
            if (r.empty()) return std::nullopt;   // the code is taken
            id = r[0][0].as<std::int64_t>();
        } catch (const pqxx::foreign_key_violation&) {
            return std::nullopt;   // no such owner
        }
        c.exec(tx, kSetMember, id, ownerId, kClassTeacher, now);
        tx.commit();
        return id;
    });
}

std::optional<ClassInfo> PostgresLabStore::classInfo(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<ClassInfo> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kClassById, id);
        if (r.empty()) return std::nullopt;
        return readClass(r[0]);
    });
}

std::optional<ClassInfo> PostgresLabStore::classByJoinCode(const std::string& code)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<ClassInfo> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kClassByCode, code);
        if (r.empty()) return std::nullopt;
        return readClass(r[0]);
    });
}

std::vector<ClassInfo> PostgresLabStore::listClasses()
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<ClassInfo> out;
        for (const auto& row : c.exec(tx, kListClasses)) out.push_back(readClass(row));
        return out;
    });
}

std::vector<Membership> PostgresLabStore::classesOf(std::int64_t userId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<Membership> out;
        for (const auto& row : c.exec(tx, kClassesOf, userId))
            out.push_back(Membership{readClass(row), row[6].as<std::string>()});
        return out;
    });
}

bool PostgresLabStore::setArchived(std::int64_t classId, bool archived)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kSetArchived, archived, classId).affected_rows() == 1;
    });
}

bool PostgresLabStore::renameClass(std::int64_t classId, const std::string& name)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kRenameClass, name, classId).affected_rows() == 1;
    });
}

bool PostgresLabStore::removeClass(std::int64_t classId)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kRemoveClass, classId).affected_rows() == 1;
    });
}

// ---- members

bool PostgresLabStore::setMember(std::int64_t classId, std::int64_t userId, const std::string& role)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        try {
            return c.exec(tx, kSetMember, classId, userId, role, static_cast<std::int64_t>(unixNow()))
                       .affected_rows() == 1;
        } catch (const pqxx::foreign_key_violation&) {
            return false;   // no such class or user
        }
    });
}

bool PostgresLabStore::removeMember(std::int64_t classId, std::int64_t userId)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kRemoveMember, classId, userId).affected_rows() == 1;
    });
}

std::optional<std::string> PostgresLabStore::memberRole(std::int64_t classId, std::int64_t userId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<std::string> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kMemberRole, classId, userId);
        if (r.empty()) return std::nullopt;
        return r[0][0].as<std::string>();
    });
}

std::vector<ClassMember> PostgresLabStore::members(std::int64_t classId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<ClassMember> out;
        for (const auto& row : c.exec(tx, kMembers, classId))
            out.push_back(ClassMember{row[0].as<std::int64_t>(), row[1].as<std::int64_t>(), row[2].as<std::string>(),
                                      row[3].as<std::string>(), row[4].as<std::int64_t>()});
        return out;
    });
}

bool PostgresLabStore::supervisesCopy(std::int64_t staffId, std::int64_t modelId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return !c.exec(tx, kSupervisesCopy, staffId, modelId).empty();
    });
}

// ---- assignments

std::optional<std::int64_t> PostgresLabStore::createAssignment(const AssignmentInfo& info,
                                                               const std::string& templateHmf,
                                                               const std::string& solutionHmf)
{
    const std::optional<std::string> solution = solutionHmf.empty() ? std::nullopt : std::optional(solutionHmf);
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) -> std::optional<std::int64_t> {
        pqxx::nontransaction tx(c.raw());
        try {
            return c.exec(tx, kCreateAssignment, info.classId, info.title, info.instructions, info.editMode,
                          info.parameters, info.opensAt, info.dueAt, templateHmf, orNull(solution),
                          static_cast<std::int64_t>(unixNow()))[0][0]
                .as<std::int64_t>();
        } catch (const pqxx::foreign_key_violation&) {
            return std::nullopt;   // no such class
        }
    });
}

std::optional<AssignmentInfo> PostgresLabStore::assignment(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<AssignmentInfo> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kAssignment, id);
        if (r.empty()) return std::nullopt;
        return readAssignment(r[0]);
    });
}

std::vector<AssignmentInfo> PostgresLabStore::assignmentsOf(std::int64_t classId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<AssignmentInfo> out;
        for (const auto& row : c.exec(tx, kAssignmentsOf, classId)) out.push_back(readAssignment(row));
        return out;
    });
}

bool PostgresLabStore::updateAssignment(const AssignmentInfo& info)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kUpdateAssignment, info.title, info.instructions, info.editMode, info.parameters,
                      info.opensAt, info.dueAt, static_cast<std::int64_t>(unixNow()), info.id)
                   .affected_rows() == 1;
    });
}

std::optional<std::int64_t> PostgresLabStore::setTemplate(std::int64_t id, const std::string& hmf)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) -> std::optional<std::int64_t> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kSetTemplate, hmf, static_cast<std::int64_t>(unixNow()), id);
        if (r.empty()) return std::nullopt;
        return r[0][0].as<std::int64_t>();
    });
}

std::optional<std::string> PostgresLabStore::templateHmf(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<std::string> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kTemplateHmf, id);
        if (r.empty()) return std::nullopt;
        return r[0][0].as<std::string>();
    });
}

bool PostgresLabStore::setSolution(std::int64_t id, const std::string& hmf, const std::string& referenceBlob)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        const auto now = static_cast<std::int64_t>(unixNow());
        // An empty solution clears both: a reference result without its solution means nothing.
        if (hmf.empty())
            return c.exec(tx, kSetSolution, static_cast<const char*>(nullptr), static_cast<const char*>(nullptr),
                          false, now, id)
                       .affected_rows() == 1;
        // Sent as binary (bytea) data.
        return c.exec(tx, kSetSolution, hmf, pqxx::binarystring(referenceBlob.data(), referenceBlob.size()), true,
                      now, id)
                   .affected_rows() == 1;
    });
}

std::optional<std::string> PostgresLabStore::solutionHmf(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<std::string> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kSolutionHmf, id);
        if (r.empty()) return std::nullopt;
        return r[0][0].as<std::string>();
    });
}

std::optional<std::string> PostgresLabStore::referenceResult(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<std::string> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kReferenceResult, id);
        if (r.empty()) return std::nullopt;
        // The text form of bytea, decoded back to the stored bytes.
        const pqxx::binarystring data(r[0][0]);
        return data.str();
    });
}

bool PostgresLabStore::removeAssignment(std::int64_t id)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kRemoveAssignment, id).affected_rows() == 1;
    });
}

// ---- checks

bool PostgresLabStore::replaceChecks(std::int64_t assignmentId, const std::vector<AssignmentCheck>& checks)
{
    // Running it twice leaves the same checks.
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::work tx(c.raw());
        if (c.exec(tx, kTouchAssignment, static_cast<std::int64_t>(unixNow()), assignmentId).affected_rows() != 1)
            return false;
        c.exec(tx, kClearChecks, assignmentId);
        // Positions are the list's order, whatever the checks' own position fields say.
        for (std::size_t i = 0; i < checks.size(); ++i)
            c.exec(tx, kInsertCheck, assignmentId, static_cast<std::int64_t>(i), checks[i].name, checks[i].pretest,
                   *textOf(std::optional(checks[i].points)), checks[i].definition);
        tx.commit();
        return true;
    });
}

std::vector<AssignmentCheck> PostgresLabStore::checks(std::int64_t assignmentId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<AssignmentCheck> out;
        for (const auto& row : c.exec(tx, kChecks, assignmentId))
            out.push_back(AssignmentCheck{row[0].as<std::int64_t>(), row[1].as<std::string>(), row[2].as<bool>(),
                                          row[3].as<double>(), row[4].as<std::string>()});
        return out;
    });
}

// ---- copies

bool PostgresLabStore::createCopy(const StudentCopy& copy)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        try {
            c.exec(tx, kCreateCopy, copy.assignmentId, copy.studentId, copy.modelId, copy.templateVersion,
                   static_cast<std::int64_t>(unixNow()));
            return true;
        } catch (const pqxx::unique_violation&) {
            return false;   // a copy of this student already, or a model that is another copy
        } catch (const pqxx::foreign_key_violation&) {
            return false;   // no such assignment, student or model
        }
    });
}

std::optional<StudentCopy> PostgresLabStore::copy(std::int64_t assignmentId, std::int64_t studentId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<StudentCopy> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kCopy, assignmentId, studentId);
        if (r.empty()) return std::nullopt;
        return readCopy(r[0]);
    });
}

std::optional<StudentCopy> PostgresLabStore::copyByModel(std::int64_t modelId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<StudentCopy> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kCopyByModel, modelId);
        if (r.empty()) return std::nullopt;
        return readCopy(r[0]);
    });
}

std::vector<StudentCopy> PostgresLabStore::copies(std::int64_t assignmentId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<StudentCopy> out;
        for (const auto& row : c.exec(tx, kCopies, assignmentId)) out.push_back(readCopy(row));
        return out;
    });
}

bool PostgresLabStore::setCopyTemplateVersion(std::int64_t assignmentId, std::int64_t studentId, std::int64_t version)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        return c.exec(tx, kSetCopyTemplateVersion, version, assignmentId, studentId).affected_rows() == 1;
    });
}

// ---- hand-ins

std::optional<HandIn> PostgresLabStore::addHandIn(const HandIn& handIn)
{
    const std::optional<std::string> jobId = textOf(handIn.jobId);
    const std::optional<std::string> grade = textOf(handIn.grade);
    const std::optional<std::string> gradedBy = textOf(handIn.gradedBy);
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) -> std::optional<HandIn> {
        const auto now = static_cast<std::int64_t>(unixNow());
        pqxx::work tx(c.raw());
        if (c.exec(tx, kLockAssignment, handIn.assignmentId).empty()) return std::nullopt;
        std::int64_t id = 0;
        try {
            id = c.exec(tx, kInsertHandIn, handIn.assignmentId, handIn.studentId, handIn.hmf, orNull(jobId),
                        handIn.handedInAt != 0 ? handIn.handedInAt : now, handIn.late,
                        *textOf(std::optional(handIn.score)), *textOf(std::optional(handIn.maxScore)),
                        handIn.checkResults, orNull(grade), orNull(gradedBy))[0][0]
                     .as<std::int64_t>();
        } catch (const pqxx::foreign_key_violation&) {
            return std::nullopt;   // no such student
        }
        const auto r = c.exec(tx, kHandIn, id);
        tx.commit();
        return readHandIn(r[0]);
    });
}

std::optional<HandIn> PostgresLabStore::handIn(std::int64_t id)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) -> std::optional<HandIn> {
        pqxx::nontransaction tx(c.raw());
        const auto r = c.exec(tx, kHandIn, id);
        if (r.empty()) return std::nullopt;
        return readHandIn(r[0]);
    });
}

std::vector<HandIn> PostgresLabStore::handIns(std::int64_t assignmentId, std::optional<std::int64_t> studentId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        const auto r = studentId ? c.exec(tx, kHandInsOfStudent, assignmentId, *studentId)
                                 : c.exec(tx, kHandInsOfAssignment, assignmentId);
        std::vector<HandIn> out;
        out.reserve(r.size());
        for (const auto& row : r) out.push_back(readHandIn(row));
        return out;
    });
}

bool PostgresLabStore::setGrade(std::int64_t handInId, std::optional<double> grade, std::int64_t gradedBy)
{
    // Clearing the grade clears who gave it.
    const std::optional<std::string> value = textOf(grade);
    const std::optional<std::string> by = grade ? textOf(std::optional(gradedBy)) : std::nullopt;
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        try {
            return c.exec(tx, kSetGrade, orNull(value), orNull(by), handInId).affected_rows() == 1;
        } catch (const pqxx::foreign_key_violation&) {
            return false;   // no such grader
        }
    });
}

// ---- comments

std::optional<std::int64_t> PostgresLabStore::addComment(std::int64_t handInId, std::int64_t authorId,
                                                         const std::string& text)
{
    return mDb.run(Idempotent::No, [&](PostgresConnection& c) -> std::optional<std::int64_t> {
        pqxx::nontransaction tx(c.raw());
        try {
            return c.exec(tx, kAddComment, handInId, authorId, text, static_cast<std::int64_t>(unixNow()))[0][0]
                .as<std::int64_t>();
        } catch (const pqxx::foreign_key_violation&) {
            return std::nullopt;   // no such hand-in or author
        }
    });
}

std::vector<HandInComment> PostgresLabStore::comments(std::int64_t handInId)
{
    return mDb.run(Idempotent::Yes, [&](PostgresConnection& c) {
        pqxx::nontransaction tx(c.raw());
        std::vector<HandInComment> out;
        for (const auto& row : c.exec(tx, kComments, handInId))
            out.push_back(HandInComment{row[0].as<std::int64_t>(), row[1].as<std::int64_t>(),
                                        row[2].as<std::int64_t>(), row[3].as<std::string>(),
                                        row[4].as<std::string>(), row[5].as<std::int64_t>()});
        return out;
    });
}

} // namespace tlmhub::server
