#include "server/store/sqlite/SqliteSchema.h"

#include "server/store/Storage.h"
#include "server/store/UnixTime.h"

#include <SQLiteCpp/Transaction.h>

#include <array>

namespace tlmhub::server {

namespace {

bool hasColumn(SQLite::Database& db, const char* table, const char* column)
{
    SQLite::Statement columns(db, std::string("PRAGMA table_info(") + table + ")");
    while (columns.executeStep())
        if (columns.getColumn(1).getString() == column) return true;
    return false;
}

// Version 1: the tables as the stores made them before migrations existed, so on such a
// database every statement finds its table already there. Owners and models are not foreign
// keys of jobs: a job's record outlives a deleted model.
void createTables(SQLite::Database& db)
{
    db.exec("CREATE TABLE IF NOT EXISTS users ("
            " id INTEGER PRIMARY KEY,"
            " username TEXT UNIQUE NOT NULL,"
            " password_hash TEXT,"
            " role TEXT CHECK(role IN ('admin','teacher','user')),"
            " created_at INTEGER,"
            " disabled INTEGER NOT NULL DEFAULT 0)");
    // Databases from before accounts could be disabled lack the column.
    if (!hasColumn(db, "users", "disabled"))
        db.exec("ALTER TABLE users ADD COLUMN disabled INTEGER NOT NULL DEFAULT 0");
    db.exec("CREATE TABLE IF NOT EXISTS models ("
            " id INTEGER PRIMARY KEY,"
            " owner_id INTEGER REFERENCES users(id),"
            " name TEXT,"
            " hmf TEXT,"
            " is_example INTEGER,"
            " created_at INTEGER,"
            " updated_at INTEGER)");
    db.exec("CREATE INDEX IF NOT EXISTS models_owner ON models(owner_id)");
    db.exec("CREATE TABLE IF NOT EXISTS sessions ("
            " token_hash TEXT PRIMARY KEY,"
            " user_id INTEGER REFERENCES users(id) ON DELETE CASCADE,"
            " expires_at INTEGER)");
    db.exec("CREATE TABLE IF NOT EXISTS meta (key TEXT PRIMARY KEY, value TEXT)");
    db.exec("CREATE TABLE IF NOT EXISTS jobs ("
            " id INTEGER PRIMARY KEY AUTOINCREMENT,"
            " owner_id INTEGER NOT NULL,"
            " model_id INTEGER,"
            " state TEXT NOT NULL,"
            " progress REAL NOT NULL DEFAULT 0,"
            " error TEXT NOT NULL DEFAULT '',"
            " created_at INTEGER NOT NULL,"
            " started_at INTEGER NOT NULL DEFAULT 0,"
            " finished_at INTEGER NOT NULL DEFAULT 0,"
            " steps INTEGER NOT NULL DEFAULT 0,"
            " start REAL NOT NULL, step REAL NOT NULL, stop REAL NOT NULL,"
            " log_samples INTEGER NOT NULL,"
            " request TEXT NOT NULL)");
    db.exec("CREATE INDEX IF NOT EXISTS jobs_owner ON jobs(owner_id)");
    db.exec("CREATE INDEX IF NOT EXISTS jobs_state ON jobs(state)");
    db.exec("CREATE TABLE IF NOT EXISTS job_results ("
            " job_id INTEGER PRIMARY KEY REFERENCES jobs(id) ON DELETE CASCADE,"
            " data BLOB NOT NULL)");
}

// Version 2: logging out everywhere and clearing expired sessions found their rows by
// scanning the table.
void indexSessions(SQLite::Database& db)
{
    db.exec("CREATE INDEX sessions_user ON sessions(user_id)");
    db.exec("CREATE INDEX sessions_expiry ON sessions(expires_at)");
}

// Version 3: personal API tokens and studies. A user's tokens and studies go with the user, a
// study's runs with the study; the model is not a foreign key, as for jobs.
void createTokensAndStudies(SQLite::Database& db)
{
    db.exec("CREATE TABLE api_tokens ("
            " id INTEGER PRIMARY KEY AUTOINCREMENT,"
            " user_id INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,"
            " name TEXT NOT NULL,"
            " token_hash TEXT UNIQUE NOT NULL,"
            " created_at INTEGER NOT NULL,"
            " expires_at INTEGER,"
            " last_used_at INTEGER)");
    db.exec("CREATE INDEX api_tokens_user ON api_tokens(user_id)");
    db.exec("CREATE TABLE studies ("
            " id INTEGER PRIMARY KEY AUTOINCREMENT,"
            " owner_id INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,"
            " model_id INTEGER,"
            " kind TEXT NOT NULL,"
            " name TEXT NOT NULL,"
            " state TEXT NOT NULL,"
            " runs_total INTEGER NOT NULL,"
            " runs_done INTEGER NOT NULL DEFAULT 0,"
            " runs_failed INTEGER NOT NULL DEFAULT 0,"
            " error TEXT NOT NULL DEFAULT '',"
            " created_at INTEGER NOT NULL,"
            " started_at INTEGER NOT NULL DEFAULT 0,"
            " finished_at INTEGER NOT NULL DEFAULT 0,"
            " request TEXT NOT NULL,"
            " summary TEXT NOT NULL DEFAULT '')");
    db.exec("CREATE INDEX studies_owner ON studies(owner_id)");
    db.exec("CREATE INDEX studies_state ON studies(state)");
    db.exec("CREATE TABLE study_runs ("
            " study_id INTEGER NOT NULL REFERENCES studies(id) ON DELETE CASCADE,"
            " run_index INTEGER NOT NULL,"
            " ok INTEGER NOT NULL,"
            " parameters TEXT NOT NULL,"
            " outputs TEXT NOT NULL,"
            " error TEXT NOT NULL DEFAULT '',"
            " result BLOB,"
            " PRIMARY KEY (study_id, run_index))");
}

// Version 4: teaching labs (server/store/LabStore.h). A class goes with everything in it; a
// user with their memberships, copies' links, hand-ins and comments (a class they own stays,
// ownerless, with its other teachers); a copy's model with the copy's link (the hand-ins keep
// their own frozen text). A hand-in's job is not a foreign key: jobs are cleaned up on their own.
void createLabs(SQLite::Database& db)
{
    db.exec("CREATE TABLE classes ("
            " id INTEGER PRIMARY KEY AUTOINCREMENT,"
            " name TEXT NOT NULL,"
            " owner_id INTEGER REFERENCES users(id) ON DELETE SET NULL,"
            " join_code TEXT UNIQUE NOT NULL,"
            " archived INTEGER NOT NULL DEFAULT 0,"
            " created_at INTEGER NOT NULL)");
    db.exec("CREATE INDEX classes_owner ON classes(owner_id)");
    db.exec("CREATE TABLE class_members ("
            " class_id INTEGER NOT NULL REFERENCES classes(id) ON DELETE CASCADE,"
            " user_id INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,"
            " role TEXT NOT NULL CHECK(role IN ('teacher','assistant','student')),"
            " joined_at INTEGER NOT NULL,"
            " PRIMARY KEY (class_id, user_id))");
    db.exec("CREATE INDEX class_members_user ON class_members(user_id)");
    db.exec("CREATE TABLE assignments ("
            " id INTEGER PRIMARY KEY AUTOINCREMENT,"
            " class_id INTEGER NOT NULL REFERENCES classes(id) ON DELETE CASCADE,"
            " title TEXT NOT NULL,"
            " instructions TEXT NOT NULL,"
            " edit_mode TEXT NOT NULL,"
            " parameters TEXT NOT NULL,"
            " opens_at INTEGER NOT NULL,"
            " due_at INTEGER NOT NULL DEFAULT 0,"
            " template_hmf TEXT NOT NULL,"
            " template_version INTEGER NOT NULL DEFAULT 1,"
            " solution_hmf TEXT,"
            " reference_result BLOB,"
            " has_solution INTEGER NOT NULL DEFAULT 0,"
            " created_at INTEGER NOT NULL,"
            " updated_at INTEGER NOT NULL)");
    db.exec("CREATE INDEX assignments_class ON assignments(class_id, opens_at)");
    db.exec("CREATE TABLE assignment_checks ("
            " assignment_id INTEGER NOT NULL REFERENCES assignments(id) ON DELETE CASCADE,"
            " position INTEGER NOT NULL,"
            " name TEXT NOT NULL,"
            " pretest INTEGER NOT NULL,"
            " points REAL NOT NULL,"
            " definition TEXT NOT NULL,"
            " PRIMARY KEY (assignment_id, position))");
    db.exec("CREATE TABLE student_copies ("
            " assignment_id INTEGER NOT NULL REFERENCES assignments(id) ON DELETE CASCADE,"
            " student_id INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,"
            " model_id INTEGER UNIQUE NOT NULL REFERENCES models(id) ON DELETE CASCADE,"
            " template_version INTEGER NOT NULL,"
            " created_at INTEGER NOT NULL,"
            " PRIMARY KEY (assignment_id, student_id))");
    db.exec("CREATE INDEX student_copies_student ON student_copies(student_id)");
    db.exec("CREATE TABLE handins ("
            " id INTEGER PRIMARY KEY AUTOINCREMENT,"
            " assignment_id INTEGER NOT NULL REFERENCES assignments(id) ON DELETE CASCADE,"
            " student_id INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,"
            " attempt INTEGER NOT NULL,"
            " hmf TEXT NOT NULL,"
            " job_id INTEGER,"
            " handed_in_at INTEGER NOT NULL,"
            " late INTEGER NOT NULL,"
            " score REAL NOT NULL,"
            " max_score REAL NOT NULL,"
            " check_results TEXT NOT NULL,"
            " grade REAL,"
            " graded_by INTEGER REFERENCES users(id) ON DELETE SET NULL,"
            " UNIQUE (assignment_id, student_id, attempt))");
    // The unique index finds an assignment's hand-ins and a student's; these serve deleting users.
    db.exec("CREATE INDEX handins_student ON handins(student_id)");
    db.exec("CREATE INDEX handins_graded_by ON handins(graded_by)");
    db.exec("CREATE TABLE handin_comments ("
            " id INTEGER PRIMARY KEY AUTOINCREMENT,"
            " handin_id INTEGER NOT NULL REFERENCES handins(id) ON DELETE CASCADE,"
            " author_id INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,"
            " text TEXT NOT NULL,"
            " created_at INTEGER NOT NULL)");
    db.exec("CREATE INDEX handin_comments_handin ON handin_comments(handin_id)");
    db.exec("CREATE INDEX handin_comments_author ON handin_comments(author_id)");
}

// Version 5: the job queue shared by several nodes (server/store/JobLeaseStore.h). A job's
// lease: the node holding it (NULL when none), when it expires and the lease number (times
// claimed, the fencing token); when it may be claimed again (backoff, ms) and whether its
// cancelling was asked; when it was last claimed (a user served longest ago goes first). Times in milliseconds since the epoch. The claim reads queued jobs by
// (state, available_at), expiry the running ones by lease_expires_at.
void addJobLeases(SQLite::Database& db)
{
    db.exec("ALTER TABLE jobs ADD COLUMN lease_node TEXT");
    db.exec("ALTER TABLE jobs ADD COLUMN lease_expires_at INTEGER NOT NULL DEFAULT 0");
    db.exec("ALTER TABLE jobs ADD COLUMN lease INTEGER NOT NULL DEFAULT 0");
    db.exec("ALTER TABLE jobs ADD COLUMN available_at INTEGER NOT NULL DEFAULT 0");
    db.exec("ALTER TABLE jobs ADD COLUMN cancel_requested INTEGER NOT NULL DEFAULT 0");
    db.exec("ALTER TABLE jobs ADD COLUMN claimed_at INTEGER NOT NULL DEFAULT 0");
    db.exec("CREATE INDEX jobs_claim ON jobs(state, available_at)");
    db.exec("CREATE INDEX jobs_owner_claimed ON jobs(owner_id, claimed_at)");
    db.exec("CREATE INDEX jobs_lease_expiry ON jobs(lease_expires_at) WHERE state = 'running'");
    db.exec("CREATE TABLE nodes ("
            " id TEXT PRIMARY KEY,"
            " role TEXT NOT NULL,"
            " address TEXT NOT NULL,"
            " last_seen INTEGER NOT NULL)");
}

// Version 6: a model's run history (issue 38). A run's name and whether it is pinned (kept
// whole); when its results were dropped to keep a model's unpinned runs within their number
// (0: not dropped). The history reads a model's jobs newest first.
void addRunHistory(SQLite::Database& db)
{
    db.exec("ALTER TABLE jobs ADD COLUMN name TEXT NOT NULL DEFAULT ''");
    db.exec("ALTER TABLE jobs ADD COLUMN pinned INTEGER NOT NULL DEFAULT 0");
    db.exec("ALTER TABLE jobs ADD COLUMN results_dropped_at INTEGER NOT NULL DEFAULT 0");
    db.exec("CREATE INDEX jobs_model ON jobs(model_id, id)");
}

// Version 7: each account's own settings (GET/PUT /preferences: display units), JSON text.
void addPreferences(SQLite::Database& db)
{
    db.exec("ALTER TABLE users ADD COLUMN preferences TEXT NOT NULL DEFAULT '{}'");
}

// Version 8: idempotency keys of POST /jobs and /studies (server/store/IdempotencyKeyStore.h),
// a day's worth per user; object_id 0 while the request that reserved the key runs. They go
// with their user.
void addIdempotencyKeys(SQLite::Database& db)
{
    db.exec("CREATE TABLE idempotency_keys ("
            " owner_id INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,"
            " key TEXT NOT NULL,"
            " route TEXT NOT NULL,"
            " request_hash TEXT NOT NULL,"
            " object_id INTEGER NOT NULL,"
            " created_at INTEGER NOT NULL,"
            " PRIMARY KEY (owner_id, key))");
    db.exec("CREATE INDEX idempotency_keys_age ON idempotency_keys(owner_id, created_at)");
}

// Version 9: studies held by nodes (issue 40). A queued or running study's node: the one that
// queues and runs it (NULL: none, e.g. released by a node that stopped). Another node takes a
// study over only when its node stops answering (the nodes table), so a restart of one node
// leaves the studies of the others alone. Each run records the node that ran it.
void addStudyNodes(SQLite::Database& db)
{
    db.exec("ALTER TABLE studies ADD COLUMN node TEXT");
    db.exec("ALTER TABLE study_runs ADD COLUMN node TEXT NOT NULL DEFAULT ''");
    db.exec("CREATE INDEX studies_active ON studies(state) WHERE state IN ('queued', 'running')");
}

// Accounts of people who sign in through a directory or a provider (UserStore::insertLinked).
void addIdentities(SQLite::Database& db)
{
    db.exec("CREATE TABLE identities ("
            " provider TEXT NOT NULL,"
            " subject TEXT NOT NULL,"
            " user_id INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,"
            " created_at INTEGER NOT NULL,"
            " PRIMARY KEY(provider, subject))");
    db.exec("CREATE INDEX identities_user ON identities(user_id)");
}

// Version 11: sign-ins through a provider between their start and its answer (SignInStore).
void addSignInAttempts(SQLite::Database& db)
{
    db.exec("CREATE TABLE sign_in_attempts ("
            " state TEXT PRIMARY KEY,"
            " provider TEXT NOT NULL,"
            " nonce TEXT NOT NULL,"
            " code_verifier TEXT NOT NULL,"
            " browser_key TEXT NOT NULL,"
            " created_at INTEGER NOT NULL,"
            " user_id INTEGER NOT NULL DEFAULT 0)");
    db.exec("CREATE INDEX sign_in_attempts_age ON sign_in_attempts(created_at)");
}

// Version 12: the learning platforms tlmhub is an LTI tool of (LtiStore).
void addLtiPlatforms(SQLite::Database& db)
{
    db.exec("CREATE TABLE lti_platforms ("
            " id INTEGER PRIMARY KEY AUTOINCREMENT,"
            " name TEXT NOT NULL,"
            " issuer TEXT NOT NULL,"
            " client_id TEXT NOT NULL,"
            " auth_url TEXT NOT NULL,"
            " token_url TEXT NOT NULL,"
            " jwks_url TEXT NOT NULL,"
            " created_at INTEGER NOT NULL,"
            " UNIQUE(issuer, client_id))");
    db.exec("CREATE TABLE lti_deployments ("
            " platform_id INTEGER NOT NULL REFERENCES lti_platforms(id) ON DELETE CASCADE,"
            " deployment_id TEXT NOT NULL,"
            " PRIMARY KEY(platform_id, deployment_id))");
    db.exec("CREATE TABLE lti_contexts ("
            " platform_id INTEGER NOT NULL REFERENCES lti_platforms(id) ON DELETE CASCADE,"
            " context_id TEXT NOT NULL,"
            " class_id INTEGER NOT NULL REFERENCES classes(id) ON DELETE CASCADE,"
            " PRIMARY KEY(platform_id, context_id))");
    db.exec("CREATE TABLE lti_line_items ("
            " platform_id INTEGER NOT NULL REFERENCES lti_platforms(id) ON DELETE CASCADE,"
            " assignment_id INTEGER NOT NULL REFERENCES assignments(id) ON DELETE CASCADE,"
            " url TEXT NOT NULL,"
            " PRIMARY KEY(platform_id, assignment_id))");
    db.exec("CREATE TABLE lti_scores ("
            " id INTEGER PRIMARY KEY AUTOINCREMENT,"
            " platform_id INTEGER NOT NULL REFERENCES lti_platforms(id) ON DELETE CASCADE,"
            " line_item_url TEXT NOT NULL,"
            " user_subject TEXT NOT NULL,"
            " user_id INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,"
            " assignment_id INTEGER NOT NULL REFERENCES assignments(id) ON DELETE CASCADE,"
            " score_given REAL NOT NULL,"
            " score_maximum REAL NOT NULL,"
            " comment TEXT NOT NULL,"
            " timestamp_ms INTEGER NOT NULL,"
            " state TEXT NOT NULL,"
            " attempts INTEGER NOT NULL DEFAULT 0,"
            " next_attempt_at INTEGER NOT NULL,"
            " last_error TEXT NOT NULL DEFAULT '',"
            " created_at INTEGER NOT NULL,"
            " delivered_at INTEGER NOT NULL DEFAULT 0,"
            " lease INTEGER NOT NULL DEFAULT 0,"
            " lease_until INTEGER NOT NULL DEFAULT 0)");
    db.exec("CREATE TABLE lti_deep_links ("
            " key TEXT PRIMARY KEY,"
            " platform_id INTEGER NOT NULL REFERENCES lti_platforms(id) ON DELETE CASCADE,"
            " deployment_id TEXT NOT NULL,"
            " return_url TEXT NOT NULL,"
            " data TEXT NOT NULL,"
            " class_id INTEGER NOT NULL REFERENCES classes(id) ON DELETE CASCADE,"
            " user_id INTEGER NOT NULL REFERENCES users(id) ON DELETE CASCADE,"
            " created_at INTEGER NOT NULL)");
    db.exec("CREATE INDEX lti_scores_due ON lti_scores(state, next_attempt_at)");
    db.exec("CREATE INDEX lti_scores_assignment ON lti_scores(assignment_id)");
}

using Migration = void (*)(SQLite::Database&);
constexpr std::array<Migration, kSchemaVersion> kMigrations{createTables,   indexSessions, createTokensAndStudies,
                                                             createLabs,     addJobLeases,  addRunHistory,
                                                             addPreferences, addIdempotencyKeys, addStudyNodes,
                                                             addIdentities, addSignInAttempts, addLtiPlatforms};

} // namespace

int sqliteSchemaVersion(SqliteConnection& connection)
{
    SQLite::Statement q(connection.db(), "SELECT COALESCE(MAX(version), 0) FROM schema_migrations");
    q.executeStep();
    return q.getColumn(0).getInt();
}

void migrateSqlite(SqliteConnection& connection)
{
    auto& db = connection.db();
    db.exec("CREATE TABLE IF NOT EXISTS schema_migrations ("
            " version INTEGER PRIMARY KEY, applied_at INTEGER NOT NULL)");
    // IMMEDIATE: two servers starting on one file take turns, and the second sees the first's
    // migrations as applied.
    for (;;) {
        SQLite::Transaction transaction(db, SQLite::TransactionBehavior::IMMEDIATE);
        const int version = sqliteSchemaVersion(connection);
        if (version > kSchemaVersion)
            throw schemaNewerThanThisServer(version);
        if (version == kSchemaVersion) return;
        kMigrations[static_cast<std::size_t>(version)](db);
        SQLite::Statement record(db, "INSERT INTO schema_migrations(version, applied_at) VALUES(?, ?)");
        record.bind(1, version + 1);
        record.bind(2, static_cast<std::int64_t>(unixNow()));
        record.exec();
        transaction.commit();
    }
}

} // namespace tlmhub::server
