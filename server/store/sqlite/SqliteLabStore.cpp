#include "server/store/UnixTime.h"
#include "server/store/sqlite/SqliteStores.h"

#include <SQLiteCpp/Transaction.h>
#include <sqlite3.h>

namespace tlmhub::server {

namespace {

// The columns each reader reads, in its order; one full text per query so each is prepared once.
#define TLMHUB_CLASS_COLUMNS "c.id, c.name, c.owner_id, c.join_code, c.archived, c.created_at"
constexpr const char* kClassById = "SELECT " TLMHUB_CLASS_COLUMNS " FROM classes c WHERE c.id = ?";
constexpr const char* kClassByCode = "SELECT " TLMHUB_CLASS_COLUMNS " FROM classes c WHERE c.join_code = ?";
constexpr const char* kClassesById = "SELECT " TLMHUB_CLASS_COLUMNS " FROM classes c ORDER BY c.id";
constexpr const char* kClassesOfUser = "SELECT " TLMHUB_CLASS_COLUMNS ", m.role FROM class_members m"
                                       " JOIN classes c ON c.id = m.class_id WHERE m.user_id = ? ORDER BY c.id";
#undef TLMHUB_CLASS_COLUMNS

#define TLMHUB_ASSIGNMENT_INFO                                                                  \
    "SELECT id, class_id, title, instructions, edit_mode, parameters, opens_at, due_at,"       \
    " template_version, has_solution, created_at, updated_at FROM assignments"
constexpr const char* kAssignmentById = TLMHUB_ASSIGNMENT_INFO " WHERE id = ?";
constexpr const char* kAssignmentsOfClass = TLMHUB_ASSIGNMENT_INFO " WHERE class_id = ? ORDER BY opens_at, id";
#undef TLMHUB_ASSIGNMENT_INFO

#define TLMHUB_COPY "SELECT assignment_id, student_id, model_id, template_version, created_at FROM student_copies"
constexpr const char* kCopyOfStudent = TLMHUB_COPY " WHERE assignment_id = ? AND student_id = ?";
constexpr const char* kCopyByModel = TLMHUB_COPY " WHERE model_id = ?";
constexpr const char* kCopiesOfAssignment = TLMHUB_COPY " WHERE assignment_id = ? ORDER BY student_id";
#undef TLMHUB_COPY

// Lists leave the frozen text out ('' in its place): it can be large and lists do not show it.
#define TLMHUB_HANDIN(hmf)                                                                      \
    "SELECT h.id, h.assignment_id, h.student_id, u.username, h.attempt, " hmf ", h.job_id,"   \
    " h.handed_in_at, h.late, h.score, h.max_score, h.check_results, h.grade, h.graded_by"     \
    " FROM handins h JOIN users u ON u.id = h.student_id"
constexpr const char* kHandInById = TLMHUB_HANDIN("h.hmf") " WHERE h.id = ?";
constexpr const char* kHandInsOfAssignment = TLMHUB_HANDIN("''") " WHERE h.assignment_id = ? ORDER BY h.id DESC";
constexpr const char* kHandInsOfStudent =
    TLMHUB_HANDIN("''") " WHERE h.assignment_id = ? AND h.student_id = ? ORDER BY h.id DESC";
#undef TLMHUB_HANDIN

bool isConstraint(const SQLite::Exception& e, std::initializer_list<int> codes)
{
    for (const int code : codes)
        if (e.getExtendedErrorCode() == code) return true;
    return false;
}

std::string readBlob(const SQLite::Column& column)
{
    // A zero-length blob comes back as a null pointer.
    if (column.getBytes() == 0) return {};
    return std::string(static_cast<const char*>(column.getBlob()), static_cast<std::size_t>(column.getBytes()));
}

ClassInfo readClass(SQLite::Statement& q)
{
    ClassInfo c;
    c.id = q.getColumn(0).getInt64();
    c.name = q.getColumn(1).getString();
    c.ownerId = q.getColumn(2).isNull() ? 0 : q.getColumn(2).getInt64();   // owner deleted
    c.joinCode = q.getColumn(3).getString();
    c.archived = q.getColumn(4).getInt() != 0;
    c.createdAt = q.getColumn(5).getInt64();
    return c;
}

AssignmentInfo readAssignment(SQLite::Statement& q)
{
    AssignmentInfo a;
    a.id = q.getColumn(0).getInt64();
    a.classId = q.getColumn(1).getInt64();
    a.title = q.getColumn(2).getString();
    a.instructions = q.getColumn(3).getString();
    a.editMode = q.getColumn(4).getString();
    a.parameters = q.getColumn(5).getString();
    a.opensAt = q.getColumn(6).getInt64();
    a.dueAt = q.getColumn(7).getInt64();
    a.templateVersion = q.getColumn(8).getInt64();
    a.hasSolution = q.getColumn(9).getInt() != 0;
    a.createdAt = q.getColumn(10).getInt64();
    a.updatedAt = q.getColumn(11).getInt64();
    return a;
}

StudentCopy readCopy(SQLite::Statement& q)
{
    return StudentCopy{q.getColumn(0).getInt64(), q.getColumn(1).getInt64(), q.getColumn(2).getInt64(),
                       q.getColumn(3).getInt64(), q.getColumn(4).getInt64()};
}

HandIn readHandIn(SQLite::Statement& q)
{
    HandIn h;
    h.id = q.getColumn(0).getInt64();
    h.assignmentId = q.getColumn(1).getInt64();
    h.studentId = q.getColumn(2).getInt64();
    h.studentName = q.getColumn(3).getString();
    h.attempt = q.getColumn(4).getInt64();
    h.hmf = q.getColumn(5).getString();
    if (!q.getColumn(6).isNull()) h.jobId = q.getColumn(6).getInt64();
    h.handedInAt = q.getColumn(7).getInt64();
    h.late = q.getColumn(8).getInt() != 0;
    h.score = q.getColumn(9).getDouble();
    h.maxScore = q.getColumn(10).getDouble();
    h.checkResults = q.getColumn(11).getString();
    if (!q.getColumn(12).isNull()) h.grade = q.getColumn(12).getDouble();
    if (!q.getColumn(13).isNull()) h.gradedBy = q.getColumn(13).getInt64();
    return h;
}

std::optional<HandIn> handInOn(SqliteConnection& c, std::int64_t id)
{
    auto q = c.prepared(kHandInById);
    q->bind(1, id);
    if (!q->executeStep()) return std::nullopt;
    return readHandIn(*q);
}

} // namespace

// ---- classes

std::optional<std::int64_t> SqliteLabStore::createClass(std::int64_t ownerId, const std::string& name,
                                                        const std::string& joinCode)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::int64_t> {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        std::int64_t id = 0;
        {
            auto insert = c.prepared("INSERT INTO classes(name, owner_id, join_code, created_at) VALUES(?, ?, ?, ?)"
                                     " ON CONFLICT(join_code) DO NOTHING");
            insert->bind(1, name);
            insert->bind(2, ownerId);
            insert->bind(3, joinCode);
            insert->bind(4, now);
            try {
                if (insert->exec() != 1) return std::nullopt;   // the code is taken
            } catch (const SQLite::Exception& e) {
                if (e.getExtendedErrorCode() == SQLITE_CONSTRAINT_FOREIGNKEY) return std::nullopt;
                throw;
            }
            id = c.db().getLastInsertRowid();
        }
        auto member = c.prepared("INSERT INTO class_members(class_id, user_id, role, joined_at) VALUES(?, ?, ?, ?)");
        member->bind(1, id);
        member->bind(2, ownerId);
        member->bind(3, kClassTeacher);
        member->bind(4, now);
        member->exec();
        transaction.commit();
        return id;
    });
}

std::optional<ClassInfo> SqliteLabStore::classInfo(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<ClassInfo> {
        auto q = c.prepared(kClassById);
        q->bind(1, id);
        if (!q->executeStep()) return std::nullopt;
        return readClass(*q);
    });
}

std::optional<ClassInfo> SqliteLabStore::classByJoinCode(const std::string& code)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<ClassInfo> {
        auto q = c.prepared(kClassByCode);
        q->bind(1, code);
        if (!q->executeStep()) return std::nullopt;
        return readClass(*q);
    });
}

std::vector<ClassInfo> SqliteLabStore::listClasses()
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared(kClassesById);
        std::vector<ClassInfo> out;
        while (q->executeStep()) out.push_back(readClass(*q));
        return out;
    });
}

std::vector<Membership> SqliteLabStore::classesOf(std::int64_t userId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared(kClassesOfUser);
        q->bind(1, userId);
        std::vector<Membership> out;
        while (q->executeStep()) out.push_back(Membership{readClass(*q), q->getColumn(6).getString()});
        return out;
    });
}

bool SqliteLabStore::setArchived(std::int64_t classId, bool archived)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("UPDATE classes SET archived = ? WHERE id = ?");
        q->bind(1, archived ? 1 : 0);
        q->bind(2, classId);
        return q->exec() == 1;
    });
}

bool SqliteLabStore::renameClass(std::int64_t classId, const std::string& name)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("UPDATE classes SET name = ? WHERE id = ?");
        q->bind(1, name);
        q->bind(2, classId);
        return q->exec() == 1;
    });
}

bool SqliteLabStore::removeClass(std::int64_t classId)
{
    // Members, assignments, checks, copies' links, hand-ins and comments go with it (ON DELETE
    // CASCADE), in the same statement.
    const bool removed = mDb.runFreeingSpace([&](SqliteConnection& c) {
        auto q = c.prepared("DELETE FROM classes WHERE id = ?");
        q->bind(1, classId);
        return q->exec() == 1;
    });
    mDb.restoreReserve();
    return removed;
}

// ---- members

bool SqliteLabStore::setMember(std::int64_t classId, std::int64_t userId, const std::string& role)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) {
        // A member keeps the time they joined when their role changes.
        auto q = c.prepared("INSERT INTO class_members(class_id, user_id, role, joined_at) VALUES(?, ?, ?, ?)"
                            " ON CONFLICT(class_id, user_id) DO UPDATE SET role = excluded.role");
        q->bind(1, classId);
        q->bind(2, userId);
        q->bind(3, role);
        q->bind(4, now);
        try {
            return q->exec() == 1;
        } catch (const SQLite::Exception& e) {
            if (e.getExtendedErrorCode() == SQLITE_CONSTRAINT_FOREIGNKEY) return false;   // no such class or user
            throw;
        }
    });
}

bool SqliteLabStore::removeMember(std::int64_t classId, std::int64_t userId)
{
    // Removing a student ends their access: on a full disk too.
    const bool removed = mDb.runFreeingSpace([&](SqliteConnection& c) {
        auto q = c.prepared("DELETE FROM class_members WHERE class_id = ? AND user_id = ?");
        q->bind(1, classId);
        q->bind(2, userId);
        return q->exec() == 1;
    });
    mDb.restoreReserve();
    return removed;
}

std::optional<std::string> SqliteLabStore::memberRole(std::int64_t classId, std::int64_t userId)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::string> {
        auto q = c.prepared("SELECT role FROM class_members WHERE class_id = ? AND user_id = ?");
        q->bind(1, classId);
        q->bind(2, userId);
        if (!q->executeStep()) return std::nullopt;
        return q->getColumn(0).getString();
    });
}

std::vector<ClassMember> SqliteLabStore::members(std::int64_t classId)
{
    return mDb.run([&](SqliteConnection& c) {
        // Names as bytes (PostgreSQL's COLLATE "C"), so both back ends list in one order.
        auto q = c.prepared("SELECT m.class_id, m.user_id, u.username, m.role, m.joined_at FROM class_members m"
                            " JOIN users u ON u.id = m.user_id WHERE m.class_id = ? ORDER BY u.username, u.id");
        q->bind(1, classId);
        std::vector<ClassMember> out;
        while (q->executeStep())
            out.push_back(ClassMember{q->getColumn(0).getInt64(), q->getColumn(1).getInt64(),
                                      q->getColumn(2).getString(), q->getColumn(3).getString(),
                                      q->getColumn(4).getInt64()});
        return out;
    });
}

bool SqliteLabStore::supervisesCopy(std::int64_t staffId, std::int64_t modelId)
{
    return mDb.run([&](SqliteConnection& c) {
        // The copy's owner must still be a student of the assignment's class: a removed
        // student's copy is nobody's to supervise.
        auto q = c.prepared("SELECT 1 FROM student_copies sc"
                            " JOIN assignments a ON a.id = sc.assignment_id"
                            " JOIN class_members s ON s.class_id = a.class_id AND s.user_id = sc.student_id"
                            "  AND s.role = 'student'"
                            " JOIN class_members t ON t.class_id = a.class_id AND t.user_id = ?"
                            "  AND t.role IN ('teacher', 'assistant')"
                            " WHERE sc.model_id = ?");
        q->bind(1, staffId);
        q->bind(2, modelId);
        return q->executeStep();
    });
}

// ---- assignments

std::optional<std::int64_t> SqliteLabStore::createAssignment(const AssignmentInfo& info, const std::string& templateHmf,
                                                             const std::string& solutionHmf)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::int64_t> {
        auto insert = c.prepared("INSERT INTO assignments(class_id, title, instructions, edit_mode, parameters,"
                                 " opens_at, due_at, template_hmf, solution_hmf, created_at, updated_at)"
                                 " VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
        insert->bind(1, info.classId);
        insert->bind(2, info.title);
        insert->bind(3, info.instructions);
        insert->bind(4, info.editMode);
        insert->bind(5, info.parameters);
        insert->bind(6, info.opensAt);
        insert->bind(7, info.dueAt);
        insert->bind(8, templateHmf);
        if (solutionHmf.empty()) insert->bind(9);
        else insert->bind(9, solutionHmf);
        insert->bind(10, now);
        insert->bind(11, now);
        try {
            insert->exec();
        } catch (const SQLite::Exception& e) {
            if (e.getExtendedErrorCode() == SQLITE_CONSTRAINT_FOREIGNKEY) return std::nullopt;   // no such class
            throw;
        }
        return c.db().getLastInsertRowid();
    });
}

std::optional<AssignmentInfo> SqliteLabStore::assignment(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<AssignmentInfo> {
        auto q = c.prepared(kAssignmentById);
        q->bind(1, id);
        if (!q->executeStep()) return std::nullopt;
        return readAssignment(*q);
    });
}

std::vector<AssignmentInfo> SqliteLabStore::assignmentsOf(std::int64_t classId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared(kAssignmentsOfClass);
        q->bind(1, classId);
        std::vector<AssignmentInfo> out;
        while (q->executeStep()) out.push_back(readAssignment(*q));
        return out;
    });
}

bool SqliteLabStore::updateAssignment(const AssignmentInfo& info)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("UPDATE assignments SET title = ?, instructions = ?, edit_mode = ?, parameters = ?,"
                            " opens_at = ?, due_at = ?, updated_at = ? WHERE id = ?");
        q->bind(1, info.title);
        q->bind(2, info.instructions);
        q->bind(3, info.editMode);
        q->bind(4, info.parameters);
        q->bind(5, info.opensAt);
        q->bind(6, info.dueAt);
        q->bind(7, now);
        q->bind(8, info.id);
        return q->exec() == 1;
    });
}

std::optional<std::int64_t> SqliteLabStore::setTemplate(std::int64_t id, const std::string& hmf)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::int64_t> {
        // The version read back is the one this update made: no writer comes in between.
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        {
            auto update = c.prepared("UPDATE assignments SET template_hmf = ?, template_version = template_version + 1,"
                                     " updated_at = ? WHERE id = ?");
            update->bind(1, hmf);
            update->bind(2, now);
            update->bind(3, id);
            if (update->exec() != 1) return std::nullopt;
        }
        std::int64_t version = 0;
        {
            auto q = c.prepared("SELECT template_version FROM assignments WHERE id = ?");
            q->bind(1, id);
            q->executeStep();
            version = q->getColumn(0).getInt64();
        }
        transaction.commit();
        return version;
    });
}

std::optional<std::string> SqliteLabStore::templateHmf(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::string> {
        auto q = c.prepared("SELECT template_hmf FROM assignments WHERE id = ?");
        q->bind(1, id);
        if (!q->executeStep()) return std::nullopt;
        return q->getColumn(0).getString();
    });
}

bool SqliteLabStore::setSolution(std::int64_t id, const std::string& hmf, const std::string& referenceBlob)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) {
        // An empty solution clears both: a reference result without its solution means nothing.
        auto q = c.prepared("UPDATE assignments SET solution_hmf = ?, reference_result = ?, has_solution = ?,"
                            " updated_at = ? WHERE id = ?");
        if (hmf.empty()) {
            q->bind(1);
            q->bind(2);
        } else {
            q->bind(1, hmf);
            // data() of an empty string is not null, so this is a zero-length blob, not NULL.
            q->bindNoCopy(2, referenceBlob.data(), static_cast<int>(referenceBlob.size()));
        }
        q->bind(3, hmf.empty() ? 0 : 1);
        q->bind(4, now);
        q->bind(5, id);
        return q->exec() == 1;
    });
}

std::optional<std::string> SqliteLabStore::solutionHmf(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::string> {
        auto q = c.prepared("SELECT solution_hmf FROM assignments WHERE id = ? AND solution_hmf IS NOT NULL");
        q->bind(1, id);
        if (!q->executeStep()) return std::nullopt;
        return q->getColumn(0).getString();
    });
}

std::optional<std::string> SqliteLabStore::referenceResult(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::string> {
        auto q = c.prepared("SELECT reference_result FROM assignments WHERE id = ? AND reference_result IS NOT NULL");
        q->bind(1, id);
        if (!q->executeStep()) return std::nullopt;
        return readBlob(q->getColumn(0));
    });
}

bool SqliteLabStore::removeAssignment(std::int64_t id)
{
    // Checks, copies' links, hand-ins and comments go with it (ON DELETE CASCADE).
    const bool removed = mDb.runFreeingSpace([&](SqliteConnection& c) {
        auto q = c.prepared("DELETE FROM assignments WHERE id = ?");
        q->bind(1, id);
        return q->exec() == 1;
    });
    mDb.restoreReserve();
    return removed;
}

// ---- checks

bool SqliteLabStore::replaceChecks(std::int64_t assignmentId, const std::vector<AssignmentCheck>& checks)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) {
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        {
            // Also tells whether the assignment exists (an empty list inserts nothing to fail).
            auto touch = c.prepared("UPDATE assignments SET updated_at = ? WHERE id = ?");
            touch->bind(1, now);
            touch->bind(2, assignmentId);
            if (touch->exec() != 1) return false;
        }
        {
            auto clear = c.prepared("DELETE FROM assignment_checks WHERE assignment_id = ?");
            clear->bind(1, assignmentId);
            clear->exec();
        }
        // Positions are the list's order, whatever the checks' own position fields say.
        for (std::size_t i = 0; i < checks.size(); ++i) {
            auto insert = c.prepared("INSERT INTO assignment_checks(assignment_id, position, name, pretest, points,"
                                     " definition) VALUES(?, ?, ?, ?, ?, ?)");
            insert->bind(1, assignmentId);
            insert->bind(2, static_cast<std::int64_t>(i));
            insert->bind(3, checks[i].name);
            insert->bind(4, checks[i].pretest ? 1 : 0);
            insert->bind(5, checks[i].points);
            insert->bind(6, checks[i].definition);
            insert->exec();
        }
        transaction.commit();
        return true;
    });
}

std::vector<AssignmentCheck> SqliteLabStore::checks(std::int64_t assignmentId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("SELECT position, name, pretest, points, definition FROM assignment_checks"
                            " WHERE assignment_id = ? ORDER BY position");
        q->bind(1, assignmentId);
        std::vector<AssignmentCheck> out;
        while (q->executeStep())
            out.push_back(AssignmentCheck{q->getColumn(0).getInt64(), q->getColumn(1).getString(),
                                          q->getColumn(2).getInt() != 0, q->getColumn(3).getDouble(),
                                          q->getColumn(4).getString()});
        return out;
    });
}

// ---- copies

bool SqliteLabStore::createCopy(const StudentCopy& copy)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) {
        auto insert = c.prepared("INSERT INTO student_copies(assignment_id, student_id, model_id, template_version,"
                                 " created_at) VALUES(?, ?, ?, ?, ?)");
        insert->bind(1, copy.assignmentId);
        insert->bind(2, copy.studentId);
        insert->bind(3, copy.modelId);
        insert->bind(4, copy.templateVersion);
        insert->bind(5, now);
        try {
            insert->exec();
        } catch (const SQLite::Exception& e) {
            // A copy of this student already, a model that is another copy, or a row that is gone.
            if (isConstraint(e, {SQLITE_CONSTRAINT_PRIMARYKEY, SQLITE_CONSTRAINT_UNIQUE, SQLITE_CONSTRAINT_FOREIGNKEY}))
                return false;
            throw;
        }
        return true;
    });
}

std::optional<StudentCopy> SqliteLabStore::copy(std::int64_t assignmentId, std::int64_t studentId)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<StudentCopy> {
        auto q = c.prepared(kCopyOfStudent);
        q->bind(1, assignmentId);
        q->bind(2, studentId);
        if (!q->executeStep()) return std::nullopt;
        return readCopy(*q);
    });
}

std::optional<StudentCopy> SqliteLabStore::copyByModel(std::int64_t modelId)
{
    return mDb.run([&](SqliteConnection& c) -> std::optional<StudentCopy> {
        auto q = c.prepared(kCopyByModel);
        q->bind(1, modelId);
        if (!q->executeStep()) return std::nullopt;
        return readCopy(*q);
    });
}

std::vector<StudentCopy> SqliteLabStore::copies(std::int64_t assignmentId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared(kCopiesOfAssignment);
        q->bind(1, assignmentId);
        std::vector<StudentCopy> out;
        while (q->executeStep()) out.push_back(readCopy(*q));
        return out;
    });
}

bool SqliteLabStore::setCopyTemplateVersion(std::int64_t assignmentId, std::int64_t studentId, std::int64_t version)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("UPDATE student_copies SET template_version = ? WHERE assignment_id = ? AND student_id = ?");
        q->bind(1, version);
        q->bind(2, assignmentId);
        q->bind(3, studentId);
        return q->exec() == 1;
    });
}

// ---- hand-ins

std::optional<HandIn> SqliteLabStore::addHandIn(const HandIn& handIn)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) -> std::optional<HandIn> {
        // IMMEDIATE: no other hand-in takes the same attempt number between the read and the insert.
        SQLite::Transaction transaction(c.db(), SQLite::TransactionBehavior::IMMEDIATE);
        std::int64_t attempt = 1;
        {
            auto last = c.prepared("SELECT COALESCE(MAX(attempt), 0) + 1 FROM handins"
                                   " WHERE assignment_id = ? AND student_id = ?");
            last->bind(1, handIn.assignmentId);
            last->bind(2, handIn.studentId);
            last->executeStep();
            attempt = last->getColumn(0).getInt64();
        }
        std::int64_t id = 0;
        {
            auto insert = c.prepared("INSERT INTO handins(assignment_id, student_id, attempt, hmf, job_id,"
                                     " handed_in_at, late, score, max_score, check_results, grade, graded_by)"
                                     " VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
            insert->bind(1, handIn.assignmentId);
            insert->bind(2, handIn.studentId);
            insert->bind(3, attempt);
            insert->bind(4, handIn.hmf);
            if (handIn.jobId) insert->bind(5, *handIn.jobId);
            else insert->bind(5);
            insert->bind(6, handIn.handedInAt != 0 ? handIn.handedInAt : now);
            insert->bind(7, handIn.late ? 1 : 0);
            insert->bind(8, handIn.score);
            insert->bind(9, handIn.maxScore);
            insert->bind(10, handIn.checkResults);
            if (handIn.grade) insert->bind(11, *handIn.grade);
            else insert->bind(11);
            if (handIn.gradedBy) insert->bind(12, *handIn.gradedBy);
            else insert->bind(12);
            try {
                insert->exec();
            } catch (const SQLite::Exception& e) {
                if (e.getExtendedErrorCode() == SQLITE_CONSTRAINT_FOREIGNKEY) return std::nullopt;
                throw;
            }
            id = c.db().getLastInsertRowid();
        }
        auto stored = handInOn(c, id);
        transaction.commit();
        return stored;
    });
}

std::optional<HandIn> SqliteLabStore::handIn(std::int64_t id)
{
    return mDb.run([&](SqliteConnection& c) { return handInOn(c, id); });
}

std::vector<HandIn> SqliteLabStore::handIns(std::int64_t assignmentId, std::optional<std::int64_t> studentId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared(studentId ? kHandInsOfStudent : kHandInsOfAssignment);
        q->bind(1, assignmentId);
        if (studentId) q->bind(2, *studentId);
        std::vector<HandIn> out;
        while (q->executeStep()) out.push_back(readHandIn(*q));
        return out;
    });
}

bool SqliteLabStore::setGrade(std::int64_t handInId, std::optional<double> grade, std::int64_t gradedBy)
{
    return mDb.run([&](SqliteConnection& c) {
        // Clearing the grade clears who gave it.
        auto q = c.prepared("UPDATE handins SET grade = ?, graded_by = ? WHERE id = ?");
        if (grade) {
            q->bind(1, *grade);
            q->bind(2, gradedBy);
        } else {
            q->bind(1);
            q->bind(2);
        }
        q->bind(3, handInId);
        try {
            return q->exec() == 1;
        } catch (const SQLite::Exception& e) {
            if (e.getExtendedErrorCode() == SQLITE_CONSTRAINT_FOREIGNKEY) return false;   // no such grader
            throw;
        }
    });
}

// ---- comments

std::optional<std::int64_t> SqliteLabStore::addComment(std::int64_t handInId, std::int64_t authorId,
                                                       const std::string& text)
{
    const auto now = static_cast<std::int64_t>(unixNow());
    return mDb.run([&](SqliteConnection& c) -> std::optional<std::int64_t> {
        auto insert = c.prepared("INSERT INTO handin_comments(handin_id, author_id, text, created_at) VALUES(?, ?, ?, ?)");
        insert->bind(1, handInId);
        insert->bind(2, authorId);
        insert->bind(3, text);
        insert->bind(4, now);
        try {
            insert->exec();
        } catch (const SQLite::Exception& e) {
            if (e.getExtendedErrorCode() == SQLITE_CONSTRAINT_FOREIGNKEY) return std::nullopt;
            throw;
        }
        return c.db().getLastInsertRowid();
    });
}

std::vector<HandInComment> SqliteLabStore::comments(std::int64_t handInId)
{
    return mDb.run([&](SqliteConnection& c) {
        auto q = c.prepared("SELECT hc.id, hc.handin_id, hc.author_id, u.username, hc.text, hc.created_at"
                            " FROM handin_comments hc JOIN users u ON u.id = hc.author_id"
                            " WHERE hc.handin_id = ? ORDER BY hc.id");
        q->bind(1, handInId);
        std::vector<HandInComment> out;
        while (q->executeStep())
            out.push_back(HandInComment{q->getColumn(0).getInt64(), q->getColumn(1).getInt64(),
                                        q->getColumn(2).getInt64(), q->getColumn(3).getString(),
                                        q->getColumn(4).getString(), q->getColumn(5).getInt64()});
        return out;
    });
}

} // namespace tlmhub::server
