#include "server/app/Bootstrap.h"
#include "server/store/Storage.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace tlmhub::server;
namespace fs = std::filesystem;

namespace {

struct BootstrapTest : ::testing::Test {
    std::unique_ptr<Storage> storage = openStorage({.database = ":memory:"});
    Accounts users{storage->users()};
    ModelStore& models = storage->models();
    MetaStore& meta = storage->meta();
    fs::path dir;

    void SetUp() override
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir = fs::temp_directory_path() / (std::string("tlmhub-bootstrap-") + info->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }

    static void copyExample(const fs::path& to)
    {
        fs::copy_file(TLMHUB_SOURCE_DIR "/examples/pressure-build-up.hmf", to,
                      fs::copy_options::overwrite_existing);
    }
    static void write(const fs::path& to, const std::string& text)
    {
        std::ofstream(to, std::ios::binary) << text;
    }
    std::vector<std::string> exampleNames()
    {
        std::vector<std::string> out;
        for (const ModelSummary& s : models.listVisibleTo(*users.findByName("admin")))
            if (s.isExample) out.push_back(s.name);
        return out;
    }
};

} // namespace

TEST_F(BootstrapTest, EnsureAdminGeneratesPasswordOnceOnly)
{
    const std::optional<std::string> generated = ensureAdmin(users, nullptr);
    ASSERT_TRUE(generated);
    EXPECT_EQ(generated->size(), 16u);
    const std::optional<User> admin = users.authenticate("admin", *generated);
    ASSERT_TRUE(admin);
    EXPECT_EQ(admin->role, "admin");

    // Second start: nothing changes, no password to print.
    EXPECT_FALSE(ensureAdmin(users, "anotherpassword"));
    EXPECT_EQ(users.count(), 1u);
    EXPECT_TRUE(users.authenticate("admin", *generated));
}

TEST_F(BootstrapTest, EnsureAdminUsesEnvironmentPassword)
{
    EXPECT_FALSE(ensureAdmin(users, "operator-chosen"));
    EXPECT_TRUE(users.authenticate("admin", "operator-chosen"));
}

TEST_F(BootstrapTest, EnsureAdminTreatsEmptyEnvAsUnsetAndRefusesShortOne)
{
    EXPECT_THROW(ensureAdmin(users, "short"), std::runtime_error);
    EXPECT_EQ(users.count(), 0u);
    const std::optional<std::string> generated = ensureAdmin(users, "");
    ASSERT_TRUE(generated);
    EXPECT_EQ(generated->size(), 16u);
}

TEST_F(BootstrapTest, SeedsEachFileOnceSortedAndNamedByStem)
{
    ensureAdmin(users, "adminpassword");
    copyExample(dir / "b-second.hmf");
    copyExample(dir / "a-first.hmf");
    write(dir / "notes.txt", "not a model");
    fs::create_directories(dir / "sub");
    copyExample(dir / "sub" / "nested.hmf");   // only the given directories, not below

    std::string log;
    EXPECT_EQ(seedExamples(models, meta, users, {dir.string()}, log), 2) << log;
    EXPECT_EQ(exampleNames(), (std::vector<std::string>{"a-first", "b-second"}));

    std::ifstream in(dir / "a-first.hmf", std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::vector<ModelSummary> all = models.listVisibleTo(*users.findByName("admin"));
    EXPECT_EQ(models.hmf(all[0].id), text);
    EXPECT_EQ(all[0].ownerName, "admin");

    // A second start adds nothing.
    log.clear();
    EXPECT_EQ(seedExamples(models, meta, users, {dir.string()}, log), 0) << log;
    EXPECT_EQ(exampleNames().size(), 2u);
}

TEST_F(BootstrapTest, DeletedExampleIsNotResurrected)
{
    ensureAdmin(users, "adminpassword");
    copyExample(dir / "only.hmf");
    std::string log;
    ASSERT_EQ(seedExamples(models, meta, users, {dir.string()}, log), 1) << log;
    models.remove(models.listVisibleTo(*users.findByName("admin")).at(0).id);

    EXPECT_EQ(seedExamples(models, meta, users, {dir.string()}, log), 0) << log;
    EXPECT_TRUE(exampleNames().empty());

    // A new file in the directory is still picked up.
    copyExample(dir / "later.hmf");
    EXPECT_EQ(seedExamples(models, meta, users, {dir.string()}, log), 1) << log;
    EXPECT_EQ(exampleNames(), (std::vector<std::string>{"later"}));
}

TEST_F(BootstrapTest, BrokenFileIsSkippedAndRetriedLater)
{
    ensureAdmin(users, "adminpassword");
    write(dir / "broken.hmf", "<hopsanmodelfile><system");
    std::string log;
    EXPECT_EQ(seedExamples(models, meta, users, {dir.string()}, log), 0);
    EXPECT_NE(log.find("broken.hmf"), std::string::npos) << log;
    EXPECT_TRUE(exampleNames().empty());

    copyExample(dir / "broken.hmf");   // fixed by the operator
    EXPECT_EQ(seedExamples(models, meta, users, {dir.string()}, log), 1) << log;
}

TEST_F(BootstrapTest, SeveralDirectoriesAndMissingDirectory)
{
    ensureAdmin(users, "adminpassword");
    fs::create_directories(dir / "one");
    fs::create_directories(dir / "two");
    copyExample(dir / "one" / "x.hmf");
    copyExample(dir / "two" / "y.hmf");
    std::string log;
    EXPECT_EQ(seedExamples(models, meta, users,
                           {(dir / "one").string(), (dir / "missing").string(),
                            (dir / "two").string()},
                           log),
              2);
    EXPECT_NE(log.find("missing"), std::string::npos) << log;
    EXPECT_EQ(exampleNames(), (std::vector<std::string>{"x", "y"}));
}

TEST_F(BootstrapTest, NothingSeededWithoutAdmin)
{
    copyExample(dir / "x.hmf");
    std::string log;
    EXPECT_EQ(seedExamples(models, meta, users, {dir.string()}, log), 0);
    EXPECT_FALSE(log.empty());
}
