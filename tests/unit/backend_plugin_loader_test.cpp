// The plugin loader: real backends load by name, and every way a plugin can
// be broken is reported in plain words naming the file.
#include "tessera/backend/PluginLoader.h"
#include "tessera/backend/RecordingBackend.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace tessera;
using namespace tessera::backend;

namespace {

std::string openError(const std::string& file) {
    auto lib = PluginLibrary::open(std::filesystem::path(TESSERA_TEST_PLUGIN_DIR) / file);
    EXPECT_FALSE(lib.ok()) << file << " unexpectedly loaded";
    return lib.ok() ? std::string() : lib.error().message;
}

PluginLoader realLoader() {
    PluginLoader loader;
    loader.addSearchDirectory(TESSERA_PLUGIN_DIR);
    return loader;
}

} // namespace

TEST(PluginLoader, LoadsEveryShippedBackendByName) {
    auto loader = realLoader();
    BackendRegistry registry;
    for (const char* name : {"null", "r2vb", "streamout", "hulldomain", "meshshader"}) {
        ASSERT_TRUE(loader.loadBackend(name, registry).ok()) << name;
        auto backend = registry.create(name);
        ASSERT_TRUE(backend.ok());
        EXPECT_EQ(backend.value()->capabilities(nullptr).name, name);
    }
}

TEST(PluginLoader, DiscoversAllBackendsAndNothingElse) {
    auto loader = realLoader();
    BackendRegistry registry;
    EXPECT_TRUE(loader.loadAll(registry).empty());
    EXPECT_EQ(registry.names(), (std::vector<std::string>{"hulldomain", "meshshader", "null", "r2vb", "streamout"}));
}

TEST(PluginLoader, UnknownBackendListsAvailableOnes) {
    auto loader = realLoader();
    BackendRegistry registry;
    auto status = loader.loadBackend("nope", registry);
    ASSERT_FALSE(status.ok());
    const std::string& msg = status.error().message;
    EXPECT_NE(msg.find("unknown backend \"nope\""), std::string::npos) << msg;
    for (const char* name : {"hulldomain", "meshshader", "null", "r2vb", "streamout"}) EXPECT_NE(msg.find(name), std::string::npos) << msg;
}

TEST(PluginLoader, ReportsMissingFile) {
    auto msg = openError("does_not_exist.so");
    EXPECT_NE(msg.find("does_not_exist.so"), std::string::npos);
    EXPECT_NE(msg.find("no such file"), std::string::npos) << msg;
}

TEST(PluginLoader, ReportsNotASharedLibrary) {
    auto msg = openError("test_plugin_not_elf.so");
    EXPECT_NE(msg.find("test_plugin_not_elf.so"), std::string::npos);
    EXPECT_NE(msg.find("not a shared library"), std::string::npos) << msg;
}

TEST(PluginLoader, ReportsMissingDependencyByName) {
    auto msg = openError("test_plugin_missing_dep.so");
    EXPECT_NE(msg.find("libtessera_test_missing_dep.so"), std::string::npos) << msg;
    EXPECT_NE(msg.find("was not found"), std::string::npos) << msg;
}

TEST(PluginLoader, ReportsAbiMismatchWithBothVersions) {
    auto msg = openError("test_plugin_abi_mismatch.so");
    EXPECT_NE(msg.find("ABI mismatch"), std::string::npos) << msg;
    EXPECT_NE(msg.find("version 1"), std::string::npos) << msg;
    EXPECT_NE(msg.find("version " + std::to_string(kPluginAbiVersion)), std::string::npos) << msg;
}

TEST(PluginLoader, ReportsModuleWithoutEntryPoint) {
    auto msg = openError("test_plugin_no_entry.so");
    EXPECT_NE(msg.find("not a Tessera plugin"), std::string::npos) << msg;
    EXPECT_NE(msg.find("registerPlugin_v" + std::to_string(kPluginAbiVersion)), std::string::npos) << msg;
}

TEST(PluginLoader, RejectsPluginThatRegistersNothing) {
    auto lib = PluginLibrary::open(std::filesystem::path(TESSERA_TEST_PLUGIN_DIR) / "test_plugin_empty.so");
    ASSERT_TRUE(lib.ok()) << lib.error().message;
    BackendRegistry registry;
    auto status = registry.addPlugin(lib.value());
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().message.find("registered no backend"), std::string::npos);
}

TEST(PluginLoader, RejectsDuplicateNameNamingBothFiles) {
    auto loader = realLoader();
    BackendRegistry registry;
    ASSERT_TRUE(loader.loadBackend("null", registry).ok());
    auto lib = PluginLibrary::open(std::filesystem::path(TESSERA_TEST_PLUGIN_DIR) / "test_plugin_duplicate.so");
    ASSERT_TRUE(lib.ok());
    auto status = registry.addPlugin(lib.value());
    ASSERT_FALSE(status.ok());
    const std::string& msg = status.error().message;
    EXPECT_NE(msg.find("already registered"), std::string::npos) << msg;
    EXPECT_NE(msg.find("test_plugin_duplicate.so"), std::string::npos) << msg;
    EXPECT_NE(msg.find("tessera_backend_null.so"), std::string::npos) << msg;
}

TEST(PluginLoader, TemplatePluginImplementsTheWholeContract) {
    PluginLoader loader;
    loader.addSearchDirectory(TESSERA_TEMPLATE_PLUGIN_DIR);
    BackendRegistry registry;
    ASSERT_TRUE(loader.loadBackend("template", registry).ok());
    auto backend = registry.create("template");
    ASSERT_TRUE(backend.ok());
    RecordingBackend recorder(*backend.value());
    ASSERT_TRUE(recorder.initialize({}).ok());
    recorder.beginFrame({});
    recorder.endFrame();
    recorder.shutdown();
    EXPECT_EQ(recorder.commands(), (std::vector<std::string>{"initialize", "beginFrame", "endFrame", "shutdown"}));
}

TEST(PluginLoader, SearchPathHonoursEnvironmentThenLibraryThenInstall) {
    const std::filesystem::path a = std::filesystem::path(TESSERA_TEST_OUTPUT_DIR) / "plugin-env-a";
    const std::filesystem::path b = std::filesystem::path(TESSERA_TEST_OUTPUT_DIR) / "plugin-env-b";
    std::filesystem::create_directories(a);
    std::filesystem::create_directories(b);
    setenv("TESSERA_PLUGIN_DIR", (a.string() + ":" + b.string()).c_str(), 1);
    PluginLoader loader;
    unsetenv("TESSERA_PLUGIN_DIR");
    loader.addSearchDirectory("/tmp/first");
    auto dirs = loader.searchDirectories();
    ASSERT_EQ(dirs.size(), 5u);
    EXPECT_EQ(dirs[0], "/tmp/first");
    EXPECT_EQ(dirs[1], a);
    EXPECT_EQ(dirs[2], b);
    // Next to libtessera_core.so (the build tree's lib/tessera), whatever the
    // executable: this test's binary is in bin/, not next to lib/.
    EXPECT_EQ(std::filesystem::canonical(dirs[3]), std::filesystem::canonical(TESSERA_PLUGIN_DIR));
    EXPECT_EQ(dirs[4], PluginLoader::installPluginDirectory());
    EXPECT_EQ(dirs[4].filename(), "tessera");
}

// A TESSERA_PLUGIN_DIR the user set but that points nowhere, or names a
// file that is not a plugin, is an error naming the path, not a silent skip.
TEST(PluginLoader, EnvironmentPointingNowhereIsAnErrorNamingIt) {
    setenv("TESSERA_PLUGIN_DIR", "/nonexistent/tessera-plugins", 1);
    PluginLoader loader;
    unsetenv("TESSERA_PLUGIN_DIR");
    BackendRegistry registry;
    auto status = loader.loadBackend("null", registry);
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().message.find("TESSERA_PLUGIN_DIR"), std::string::npos) << status.error().message;
    EXPECT_NE(status.error().message.find("/nonexistent/tessera-plugins"), std::string::npos) << status.error().message;
    const auto errors = loader.loadAll(registry);
    ASSERT_FALSE(errors.empty());
    EXPECT_NE(errors.front().message.find("/nonexistent/tessera-plugins"), std::string::npos);
}

TEST(PluginLoader, EnvironmentNamingANonPluginFileIsAnErrorNamingIt) {
    const std::filesystem::path file = std::filesystem::path(TESSERA_TEST_OUTPUT_DIR) / "not_a_plugin.txt";
    { std::ofstream(file) << "hello"; }
    setenv("TESSERA_PLUGIN_DIR", file.c_str(), 1);
    PluginLoader loader;
    unsetenv("TESSERA_PLUGIN_DIR");
    BackendRegistry registry;
    auto status = loader.loadBackend("null", registry);
    ASSERT_FALSE(status.ok());
    const std::string& msg = status.error().message;
    EXPECT_NE(msg.find("TESSERA_PLUGIN_DIR"), std::string::npos) << msg;
    EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
    EXPECT_NE(msg.find("not a shared library"), std::string::npos) << msg;
}

TEST(PluginLoader, EnvironmentNamingAPluginFileLoadsIt) {
    const std::filesystem::path file = std::filesystem::path(TESSERA_PLUGIN_DIR) / PluginLoader::moduleFileName("null");
    setenv("TESSERA_PLUGIN_DIR", file.c_str(), 1);
    PluginLoader loader;
    unsetenv("TESSERA_PLUGIN_DIR");
    BackendRegistry registry;
    auto status = loader.loadBackend("null", registry);
    ASSERT_TRUE(status.ok()) << status.error().message;
    EXPECT_TRUE(registry.contains("null"));
}
