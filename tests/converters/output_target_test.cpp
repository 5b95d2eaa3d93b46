// Where finished output goes: a regular file is replaced by a temporary renamed into place, but a
// symbolic link must stay a link (the file it names is replaced) and a device or pipe must be
// written in place - renaming over /dev/null as root would replace the device with a file.
// Pipes stand in for devices here: any user can make one.
#include <gtest/gtest.h>

#include "converters/rays/io.h"
#include "support/test_support.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <filesystem>
#include <thread>

namespace {

using namespace rayset;
namespace fs = std::filesystem;

// A FIFO and a thread that reads all that is written into it. Both ends are opened here, on the
// FIFO itself: if a writer replaced the path instead of writing into it, finish() still ends
// (with nothing received) rather than waiting for ever.
class Fifo {
public:
    explicit Fifo(std::string path) : path_(std::move(path)) {
        if (::mkfifo(path_.c_str(), 0600) != 0) throw std::runtime_error("mkfifo failed");
        read_end_ = ::open(path_.c_str(), O_RDONLY | O_NONBLOCK);  // does not wait for a writer
        keeper_ = ::open(path_.c_str(), O_WRONLY);                 // a writer until finish()
        if (read_end_ < 0 || keeper_ < 0) throw std::runtime_error("cannot open the FIFO");
        ::fcntl(read_end_, F_SETFL, ::fcntl(read_end_, F_GETFL) & ~O_NONBLOCK);
        reader_ = std::thread([this] {
            char buffer[4096];
            for (ssize_t got; (got = ::read(read_end_, buffer, sizeof buffer)) > 0;)
                received_.append(buffer, size_t(got));
        });
    }
    ~Fifo() { finish(); }
    // Everything written, once every writer has closed the FIFO (the keeper is closed here).
    const std::string& finish() {
        if (reader_.joinable()) {
            ::close(keeper_);
            reader_.join();
            ::close(read_end_);
        }
        return received_;
    }
    const std::string& path() const { return path_; }

private:
    std::string path_;
    int read_end_ = -1, keeper_ = -1;
    std::string received_;
    std::thread reader_;
};

int leftovers(const fs::path& dir) {  // temporary files left in a folder
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().rfind('.', 0) == 0) ++n;
    return n;
}

TEST(AtomicOutput, WritesThroughASymbolicLinkWhichStaysALink) {
    test::ScratchDir dir;
    const std::string file = dir.file("data.csv"), link = dir.file("link.csv");
    test::write_file(file, "old");
    fs::create_symlink(file, link);
    AtomicOutput out(link);
    out.write(std::string_view("new"));
    out.commit();
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(test::read_file(file), "new");
    EXPECT_EQ(leftovers(dir.path()), 0);
}

TEST(AtomicOutput, WritesIntoAPipeInPlace) {
    test::ScratchDir dir;
    Fifo fifo(dir.file("pipe"));
    {
        AtomicOutput out(fifo.path());
        out.write(std::string_view("hello, "));
        out.write(std::string(100000, 'x'));  // more than the buffer: written straight through
        out.commit();
    }
    EXPECT_EQ(fifo.finish(), "hello, " + std::string(100000, 'x'));
    EXPECT_TRUE(fs::is_fifo(fifo.path()));
    EXPECT_EQ(leftovers(dir.path()), 0);
}

TEST(AtomicOutput, PatchingAPipeFailsNamingItAndWhy) {
    test::ScratchDir dir;
    Fifo fifo(dir.file("pipe"));
    std::string message;
    try {
        AtomicOutput out(fifo.path());
        out.write(std::string(64, 'h'));
        const uint32_t count = 7;
        out.patch(8, &count, sizeof count);
    } catch (const Error& e) {
        message = e.what();
    }
    fifo.finish();
    EXPECT_EQ(message.find(fifo.path() + ": "), 0u) << message;
    EXPECT_NE(message.find("pipe"), std::string::npos) << message;
    EXPECT_TRUE(fs::is_fifo(fifo.path()));
}

TEST(AtomicOutput, RefusesAFolder) {
    test::ScratchDir dir;
    EXPECT_THROW(AtomicOutput out(dir.path().string()), Error);
    EXPECT_TRUE(fs::is_directory(dir.path()));
}

TEST(WriteAtomically, WritesThroughALinkAndIntoAPipe) {
    test::ScratchDir dir;
    auto writer = [](const std::string& text) {
        return [text](const std::string& path) {
            test::write_file(path, text);
            return true;
        };
    };
    const std::string file = dir.file("model.vdb"), link = dir.file("link.vdb");
    test::write_file(file, "old");
    fs::create_symlink(file, link);
    write_atomically(link, writer("new"));
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_EQ(test::read_file(file), "new");

    Fifo fifo(dir.file("pipe"));
    write_atomically(fifo.path(), writer("streamed"));
    EXPECT_EQ(fifo.finish(), "streamed");
    EXPECT_TRUE(fs::is_fifo(fifo.path()));
    EXPECT_EQ(leftovers(dir.path()), 0);
}

// Two writers of one output at once (two commands run by a script, say) each write their own
// temporary file: the one that finishes last is what stays, and neither fails or leaves a
// temporary behind. A fixed temporary name would let the second writer take the first one's.
TEST(WriteAtomically, TwoWritersOfOnePathAtOnceEachFinish) {
    test::ScratchDir dir;
    const std::string file = dir.file("model.vdb");
    std::string inner_temporary, outer_temporary;
    write_atomically(file, [&](const std::string& outer) {
        outer_temporary = outer;
        test::write_file(outer, "outer");
        write_atomically(file, [&](const std::string& inner) {
            inner_temporary = inner;
            test::write_file(inner, "inner");
            return true;
        });
        EXPECT_EQ(test::read_file(file), "inner");
        return true;
    });
    EXPECT_NE(inner_temporary, outer_temporary);
    EXPECT_EQ(fs::path(outer_temporary).extension(), ".vdb");  // kept for writers that go by it
    EXPECT_EQ(test::read_file(file), "outer");
    EXPECT_EQ(leftovers(dir.path()), 0);
}

TEST(AtomicOutput, TwoWritersOfOnePathAtOnceEachFinish) {
    test::ScratchDir dir;
    const std::string file = dir.file("rays.csv");
    AtomicOutput first(file), second(file);
    first.write(std::string_view("first"));
    second.write(std::string_view("second"));
    second.commit();
    first.commit();
    EXPECT_EQ(test::read_file(file), "first");
    EXPECT_EQ(leftovers(dir.path()), 0);
}

// A writer that says it succeeded but wrote nothing (some fail silently) leaves the user's file.
TEST(WriteAtomically, AnOutputLeftEmptyReplacesNothing) {
    test::ScratchDir dir;
    const std::string file = dir.file("scene.vtp");
    test::write_file(file, "the user's scene");
    EXPECT_THROW(write_atomically(file, [](const std::string&) { return true; }), Error);
    EXPECT_EQ(test::read_file(file), "the user's scene");
    EXPECT_EQ(leftovers(dir.path()), 0);
}

TEST(RayconvOutput, ConvertsIntoAPipeWhatItWritesToAFile) {
    test::ScratchDir dir;
    const std::string rays = dir.file("disk.tm25ray"), csv = dir.file("disk.csv");
    auto run = [](const std::string& args) {
        return test::run_command(std::string(RAYCONV_EXE) + " " + args);
    };
    ASSERT_EQ(
        run("synth disk radius=1 flux=1 wavelength=550 --rays 2000 --seed 3 -o " + rays).status, 0);
    ASSERT_EQ(run("convert " + rays + " " + csv).status, 0);
    Fifo fifo(dir.file("pipe"));
    const auto result = run("convert " + rays + " " + fifo.path() + " --to csv");
    EXPECT_EQ(result.status, 0) << result.output;
    EXPECT_EQ(fifo.finish(), test::read_file(csv));
    EXPECT_TRUE(fs::is_fifo(fifo.path()));
}

}  // namespace
