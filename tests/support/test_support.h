// Helpers shared by the tests: scratch folders, paths of the real sample files, running tools.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rayset::test {

// A fresh, empty folder for one test, removed when the object goes away.
class ScratchDir {
public:
    ScratchDir();
    ~ScratchDir();
    const std::filesystem::path& path() const { return path_; }
    std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

// A folder on a file system of `bytes` (a tmpfs mounted for the test, unmounted when the object
// goes away), to see how tools fail when the disk fills up. Mounting needs root: mounted() is
// false otherwise, and why() says so.
class SmallDisk {
public:
    explicit SmallDisk(size_t bytes);
    ~SmallDisk();
    bool mounted() const { return mounted_; }
    const std::string& why() const { return why_; }
    std::string file(const std::string& name) const { return dir_.file(name); }
    // The names in the folder, sorted.
    std::vector<std::string> names() const;

private:
    ScratchDir dir_;
    bool mounted_ = false;
    std::string why_;
};

// Path of a file in ../shared/data (e.g. "rayfiles/Cyl10k.1.tm25ray"); the calling test is
// skipped with a clear message when the folder is not there (a fresh user machine).
std::string shared_data(const std::string& relative);
bool have_shared_data();

// Runs a command line through the shell; returns its exit status and captures stdout+stderr.
struct CommandResult {
    int status = -1;
    std::string output;
};
CommandResult run_command(const std::string& command_line);

// Starts `argv` (stdout and stderr to /dev/null; in `folder` unless empty), sends it SIGKILL
// after `seconds` unless it has ended by then, and waits for it. Returns true when the kill came
// first.
bool killed_after(const std::vector<std::string>& argv, double seconds,
                  const std::string& folder = "");

// Writes bytes to a file (for hand-made bad inputs).
void write_file(const std::string& path, const std::string& bytes);
std::string read_file(const std::string& path);

}  // namespace rayset::test

// Skips the current test when the shared real data is absent.
#define RAYSET_REQUIRE_SHARED_DATA()                                            \
    do {                                                                        \
        if (!::rayset::test::have_shared_data())                                \
            GTEST_SKIP() << "../shared/data not found: real-data test skipped"; \
    } while (0)
