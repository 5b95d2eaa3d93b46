// raytrace stopped and resumed (issue 6): SIGINT and SIGTERM leave complete outputs of the last
// completed pass and a checkpoint, exit 130 / 143 and say how to resume; SIGKILL leaves the
// last checkpoint valid; `--resume` then writes the very files of an uninterrupted render and
// ends with its statistics. Bad checkpoints (truncated, another version, another scene or
// seed, not a checkpoint, missing) are refused with a message naming the fault, and no file
// in the folder changes.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <map>
#include <thread>

#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/random.h"
#include "support/test_support.h"
#include "tracer/film/checkpoint.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer {
namespace {

namespace fs = std::filesystem;

const std::string kRaytrace = std::string(RAYSET_BINARY_DIR) + "/tracer/raytrace";
const std::string kCornell = (fs::path(__FILE__).parent_path() / "scenes" / "cornell.pov").string();

std::vector<std::string> arguments(int passes, int seed = 3, int width = 48) {
    return {"scene.pov",
            "+W" + std::to_string(width),
            "+H36",
            "-o",
            "out.exr",
            "--passes",
            std::to_string(passes),
            "--seed",
            std::to_string(seed),
            "-q",
            "--checkpoint-interval",
            "0"};
}
// Enough passes that the render is still running when the test signals it (about 2 s on
// one core).
const std::vector<std::string> kArguments = arguments(300);

test::CommandResult raytrace(const std::vector<std::string>& arguments, const std::string& folder) {
    std::string line = "cd '" + folder + "' && '" + kRaytrace + "'";
    for (const std::string& a : arguments) line += " '" + a + "'";
    return test::run_command(line);
}

std::vector<std::string> with(std::vector<std::string> arguments,
                              const std::vector<std::string>& more) {
    arguments.insert(arguments.end(), more.begin(), more.end());
    return arguments;
}

// A folder with the Cornell box as scene.pov and a receiver on its floor.
struct RenderFolder {
    test::ScratchDir dir;
    RenderFolder() {
        test::write_file(dir.file("scene.pov"),
                         test::read_file(kCornell) +
                             "illuminance_receiver { <5, 0.01, 5>, <0, 0, 45>, <45, 0, 0> "
                             "resolution <4, 3> name \"floor\" }\n");
    }
    std::string folder() const { return dir.path().string(); }
    std::map<std::string, std::string> files() const {
        std::map<std::string, std::string> contents;
        for (const auto& entry : fs::directory_iterator(dir.path()))
            contents[entry.path().filename().string()] = test::read_file(entry.path().string());
        return contents;
    }
};

// Starts raytrace in `folder`, output to `folder`/log; waits for `file` to appear there, sends
// `signal`, and returns the exit status (128 + signal for a process the signal killed).
int interrupt_when_present(const std::vector<std::string>& arguments, const std::string& folder,
                           const std::string& file, int signal) {
    std::vector<std::string> words = with({kRaytrace}, arguments);
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    const std::string log = folder + "/log";
    const pid_t pid = fork();
    if (pid == 0) {  // only async-signal-safe calls until exec
        const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd < 0 || chdir(folder.c_str()) != 0 || dup2(fd, 1) < 0 || dup2(fd, 2) < 0) _exit(126);
        execv(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (!fs::exists(folder + "/" + file)) {
        if (waitpid(pid, &status, WNOHANG) == pid) {
            ADD_FAILURE() << "raytrace ended before " << file << " appeared:\n"
                          << test::read_file(log);
            return -1;
        }
        if (std::chrono::steady_clock::now() > deadline) signal = SIGKILL;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    kill(pid, signal);
    waitpid(pid, &status, 0);
    return WIFEXITED(status)     ? WEXITSTATUS(status)
           : WIFSIGNALED(status) ? 128 + WTERMSIG(status)
                                 : -1;
}

// Passes recorded in an EXR, after reading every pixel (an incomplete file throws).
int exr_samples(const std::string& path) {
    Imf::InputFile file(path.c_str());
    const auto window = file.header().dataWindow();
    std::vector<float> values(size_t(window.max.x - window.min.x + 1) *
                              (window.max.y - window.min.y + 1));
    Imf::FrameBuffer frame;
    frame.insert("Y", Imf::Slice(Imf::FLOAT, (char*)values.data(), sizeof(float),
                                 sizeof(float) * size_t(window.max.x - window.min.x + 1)));
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);
    for (const char* key : {"rayset_samples_per_pixel", "rayset_samples_per_cell"})
        if (const auto* a = file.header().findTypedAttribute<Imf::StringAttribute>(key))
            return std::stoi(a->value());
    return -1;
}

// The state in a checkpoint the tool wrote with kArguments.
RenderResult read_tool_checkpoint(const RenderFolder& f) {
    const SceneDescription description = parse_scene_file(f.dir.file("scene.pov"));
    RenderSettings settings;
    settings.width = 48, settings.height = 36, settings.seed = 3;
    return read_checkpoint(f.dir.file("out.checkpoint"), checkpoint_identity(description, settings),
                           blank_render(description, settings));
}

TEST(RaytraceResume, InterruptedRendersResumeToTheUninterruptedFiles) {
    RenderFolder reference;
    const auto whole = raytrace(with(kArguments, {"--keep-checkpoint"}), reference.folder());
    ASSERT_EQ(whole.status, 0) << whole.output;
    const auto expected = reference.files();
    const RenderResult expected_state = read_tool_checkpoint(reference);
    ASSERT_EQ(expected_state.passes, 300);

    for (int signal : {SIGINT, SIGTERM, SIGKILL}) {
        SCOPED_TRACE(strsignal(signal));
        RenderFolder f;
        const int status = interrupt_when_present(kArguments, f.folder(), "out.checkpoint", signal);
        EXPECT_EQ(status, 128 + signal) << test::read_file(f.dir.file("log"));
        const RenderResult stopped = read_tool_checkpoint(f);
        EXPECT_GE(stopped.passes, 1);
        EXPECT_LT(stopped.passes, 300);
        if (signal != SIGKILL) {
            // The outputs of the last completed pass: whole files, of the checkpoint's passes.
            EXPECT_NE(test::read_file(f.dir.file("log")).find("--resume"), std::string::npos);
            for (const char* exr : {"out.exr", "out.floor.exr"})
                EXPECT_EQ(exr_samples(f.dir.file(exr)), stopped.passes) << exr;
            EXPECT_EQ(test::read_file(f.dir.file("out.png")).substr(0, 8),
                      std::string("\x89PNG\r\n\x1a\n", 8));
        }
        const auto resumed =
            raytrace(with(kArguments, {"--resume", "--keep-checkpoint"}), f.folder());
        ASSERT_EQ(resumed.status, 0) << resumed.output;
        const RenderResult state = read_tool_checkpoint(f);
        EXPECT_EQ(state.passes, expected_state.passes);
        EXPECT_EQ(state.rays, expected_state.rays);
        for (const char* file : {"out.exr", "out.png", "out.floor.exr", "out.floor.csv"})
            EXPECT_TRUE(test::read_file(f.dir.file(file)) == expected.at(file))
                << file << " differs";
        // Without --keep-checkpoint a completed render removes it.
        ASSERT_EQ(raytrace(with(kArguments, {"--resume"}), f.folder()).status, 0);
        EXPECT_FALSE(fs::exists(f.dir.file("out.checkpoint")));
        EXPECT_TRUE(test::read_file(f.dir.file("out.exr")) == expected.at("out.exr"));
    }
}

// SIGKILL at moments drawn uniformly over 1.2 times an uninterrupted render, a checkpoint after
// every pass: whatever moment the kill lands on (a pass, a checkpoint or the outputs being
// written), each output holds what was there before or a whole file, the checkpoint reads, and
// resuming from it (or starting again when there is none) writes the uninterrupted render's
// very files. A killed process can leave nothing else but its hidden temporary files. The
// moments are measured against one render timed first; should the machine slow down after it so
// that no kill lands after the first checkpoint, one more render is killed once its checkpoint
// is there, so that resuming a killed render is always exercised.
TEST(RaytraceResume, RendersKilledAtRandomMomentsResumeToTheUninterruptedFiles) {
    const std::vector<std::string> kill_arguments = arguments(100);
    RenderFolder reference;
    const auto start = std::chrono::steady_clock::now();
    ASSERT_EQ(raytrace(kill_arguments, reference.folder()).status, 0);
    const double whole =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto expected = reference.files();

    int with_checkpoint = 0, temporaries = 0;
    // What a killed render left, and its resumption.
    auto check_and_resume = [&](RenderFolder& f) {
        const std::string exr = test::read_file(f.dir.file("out.exr"));
        if (exr != "previous") {
            const int samples = exr_samples(f.dir.file("out.exr"));
            EXPECT_GE(samples, 1);
            EXPECT_LE(samples, 100);
        }
        std::vector<std::string> resume = kill_arguments;
        if (fs::exists(f.dir.file("out.checkpoint"))) {
            const RenderResult stopped = read_tool_checkpoint(f);
            EXPECT_GE(stopped.passes, 1);
            EXPECT_LE(stopped.passes, 100);
            resume.push_back("--resume");
            ++with_checkpoint;
        }
        for (const auto& [name, contents] : f.files()) {
            if (name == "scene.pov" || name == "out.checkpoint" || expected.count(name)) continue;
            const bool temporary = name[0] == '.' && name.find(".tmp") != std::string::npos;
            EXPECT_TRUE(temporary) << "a killed render left " << name;
            temporaries += temporary;
        }
        const auto resumed = raytrace(resume, f.folder());
        ASSERT_EQ(resumed.status, 0) << resumed.output;
        for (const auto& [name, contents] : expected)
            EXPECT_TRUE(test::read_file(f.dir.file(name)) == contents) << name << " differs";
    };

    Pcg32 rng(5);
    int killed = 0;
    for (int round = 0; round < 8; ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        RenderFolder f;
        test::write_file(f.dir.file("out.exr"), "previous");
        killed += test::killed_after(with({kRaytrace}, kill_arguments), 1.2 * whole * rng.uniform(),
                                     f.folder());
        check_and_resume(f);
    }
    const int random_with_checkpoint = with_checkpoint;
    if (with_checkpoint == 0) {
        SCOPED_TRACE("killed once its checkpoint is there");
        RenderFolder f;
        test::write_file(f.dir.file("out.exr"), "previous");
        EXPECT_EQ(interrupt_when_present(kill_arguments, f.folder(), "out.checkpoint", SIGKILL),
                  128 + SIGKILL);
        check_and_resume(f);
    }
    EXPECT_GE(killed, 4);  // P(fewer than 4 of 8 kills before the end) ~ 0.5% at p = 5/6
    EXPECT_GE(with_checkpoint, 1);
    std::printf("[ figures  ] %d of 8 renders killed, %d left a checkpoint, %d temporary files\n",
                killed, random_with_checkpoint, temporaries);
}

TEST(RaytraceResume, BadCheckpointsAreRefusedAndNothingChanges) {
    RenderFolder f;
    ASSERT_EQ(raytrace(with(arguments(2), {"--keep-checkpoint"}), f.folder()).status, 0);
    const std::string good = test::read_file(f.dir.file("out.checkpoint"));
    const std::string scene = test::read_file(f.dir.file("scene.pov"));
    const std::vector<std::string> resume = with(arguments(4), {"--resume"});

    auto expect_refused = [&](const std::vector<std::string>& arguments,
                              const std::string& message) {
        const auto before = f.files();
        const auto r = raytrace(arguments, f.folder());
        EXPECT_EQ(r.status, 1) << r.output;
        EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
        EXPECT_TRUE(f.files() == before) << "a file changed or appeared after: " << r.output;
    };
    test::write_file(f.dir.file("out.checkpoint"), good.substr(0, good.size() / 2));
    expect_refused(resume, "out.checkpoint: truncated or corrupt checkpoint");
    test::write_file(f.dir.file("out.checkpoint"), good.substr(0, 10));
    expect_refused(resume, "out.checkpoint: truncated checkpoint");

    std::string other_version = good;
    other_version[8] = 9;
    test::write_file(f.dir.file("out.checkpoint"), other_version);
    expect_refused(resume, "checkpoint format version 9; this raytrace reads version 1");

    test::write_file(f.dir.file("out.checkpoint"), "P6\n48 36\n255\n");
    expect_refused(resume, "out.checkpoint: not a raytrace checkpoint");

    test::write_file(f.dir.file("out.checkpoint"), good);
    test::write_file(f.dir.file("scene.pov"),
                     scene + "sphere { <27, 10, 20>, 5 pigment { rgb 1 } }\n");
    expect_refused(resume, "the scene, an included file or a data file changed");
    test::write_file(f.dir.file("scene.pov"), scene);
    expect_refused(with(arguments(4, 4, 40), {"--resume"}),
                   "it has\n  width 48 (this render: 40)\n  seed 3 (this render: 4)");

    fs::remove(f.dir.file("out.checkpoint"));
    expect_refused(resume, "out.checkpoint: no checkpoint to resume from");

    // The good checkpoint again: it resumes.
    test::write_file(f.dir.file("out.checkpoint"), good);
    const auto r = raytrace(resume, f.folder());
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_EQ(exr_samples(f.dir.file("out.exr")), 4);
}

TEST(RaytraceResume, HelpDescribesStopAndResume) {
    const auto r = test::run_command("'" + kRaytrace + "' --help");
    EXPECT_EQ(r.status, 0);
    for (const char* text : {"Stop and resume", "OUT.checkpoint", "--resume", "--keep-checkpoint",
                             "--checkpoint-interval"})
        EXPECT_NE(r.output.find(text), std::string::npos) << text;
}

}  // namespace
}  // namespace rayset::tracer
