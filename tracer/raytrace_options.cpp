// Parsing raytrace's command line, POV-Ray switches and .ini files (see raytrace_options.h).
#include "tracer/raytrace_options.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "core/error.h"
#include "tracer/render/integrator.h"

namespace rayset::tracer {

namespace {

constexpr const char* kDescription =
    R"(raytrace: render a POV-Ray-style scene with a physically based path tracer.

Writes OUT.exr (linear R,G,B radiance in W/(m^2 sr) per linear-sRGB channel, and Y, the
luminance in cd/m^2 = 683 * (0.2126 R + 0.7152 G + 0.0722 B)), a PNG preview (sRGB, auto
exposure) and, for each illuminance_receiver of the scene, OUT.NAME.exr and OUT.NAME.csv
(illuminance in lux with its standard error, irradiance in W/m^2), and the same again for
each light layer, OUT.direct_visibility.*, OUT.primary.* and OUT.secondary.*: a light's body
seen straight or in mirrors, light straight from a light reflected once, and the rest; what
no layer holds (emitting surfaces, the background, fog) is in OUT.exr only. Files appear only
when complete. Light units: a light's colour is its radiant intensity in W/sr per channel; see
tracer/render/README.md for every convention.

Examples:
  raytrace cornell.pov +W640 +H480 +Ocornell.exr --passes 64
  raytrace scene.pov --time 60 --threads 2 --seed 7 -o out/scene.exr
  raytrace render.ini
      (Width=, Height=, Input_File_Name=, Output_File_Name=, Library_Path=)

Stop and resume: while it renders, raytrace keeps OUT.checkpoint (OUT.exr with .checkpoint),
the state after a completed pass: written after the first pass, then at most every
--checkpoint-interval seconds, always whole (temporary file renamed). Ctrl-C (SIGINT) or
SIGTERM abandons the pass under way, writes the outputs and the checkpoint of the last
completed pass and exits with 130 or 143; a second Ctrl-C exits at once. The same command with
--resume continues: the result is bit for bit that of an uninterrupted render (--passes and
--time count what is already done). After a kill -9 the last checkpoint is intact (a hidden
.OUT.tmpNNNNNN.EXT file beside an output is what a killed write left: delete it); --resume with the
budget already reached only writes its outputs. A checkpoint of another scene, size,
seed or integrator setting is refused, naming what differs. A completed render removes the
checkpoint (--keep-checkpoint keeps it, to add passes later).

Several processes or machines: mpirun -n N raytrace ... (or srun) shares the passes among N
processes (give each --threads); rank 0 writes the files and checkpoints. The result equals the
one-process render up to the order of floating-point sums, the same bits for a given N; a
Slurm script: examples/slurm_render.sh.

POV-Ray switches: +Wn width, +Hn height, +Ofile output, +Ifile scene, +Ldir include folder;
animation: +Kn clock, +KFIn / +KFFn initial / final frame, +KIn / +KFn initial / final clock,
+SFn / +EFn subset start / end frame (.ini: Clock=, Initial_Frame=, Final_Frame=, Initial_Clock=,
Final_Clock=, Subset_Start_Frame=, Subset_End_Frame=). One frame is rendered per run: the first
of the subset, with clock and frame_number as POV-Ray sets them; choose it with +SF.
Precedence: .ini files, then + switches, then the options below.)";

std::string trim(const std::string& s) {
    const auto begin = s.find_first_not_of(" \t\r\n");
    if (begin == std::string::npos) return "";
    return s.substr(begin, s.find_last_not_of(" \t\r\n") - begin + 1);
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

int parse_size(const std::string& value, const std::string& what, const std::string& where) {
    try {
        size_t used = 0;
        const long v = std::stol(value, &used);
        if (used == value.size() && v >= 1 && v <= kMaxImageSide) return int(v);
    } catch (const std::exception&) {
    }
    throw Error(fmt::format("{}: {} must be a whole number from 1 to {}, got '{}'", where, what,
                            kMaxImageSide, value));
}

double parse_number(const std::string& value, const std::string& what, const std::string& where) {
    try {
        size_t used = 0;
        const double v = std::stod(value, &used);
        if (used == value.size() && std::isfinite(v)) return v;
    } catch (const std::exception&) {
    }
    throw Error(fmt::format("{}: {} must be a number, got '{}'", where, what, value));
}

int parse_frame(const std::string& value, const std::string& what, const std::string& where) {
    const double v = parse_number(value, what, where);
    if (v != std::floor(v) || std::abs(v) > 1e9)
        throw Error(
            fmt::format("{}: {} must be a whole frame number, got '{}'", where, what, value));
    return int(v);
}

bool ends_with_ini(const std::string& arg) {
    return arg.size() > 4 && lower(arg.substr(arg.size() - 4)) == ".ini";
}

// A setting that a + switch and an .ini key both give; `apply` reads its value (`what` names it
// in messages, `where` is the command line or FILE:LINE).
using Text = const std::string&;
struct PovSetting {
    const char* switch_name;  // after '+', upper case
    const char* ini_key;      // lower case
    const char* what;
    void (*apply)(Text value, Text what, Text where, RaytraceOptions& o);
};

// Longer switch names first: +KFI and +KFF before +KF before +K.
const PovSetting kPovSettings[] = {
    {"KFI", "initial_frame", "Initial_Frame (+KFI)",
     [](Text v, Text what, Text where, RaytraceOptions& o) {
         o.animation.initial_frame = parse_frame(v, what, where);
     }},
    {"KFF", "final_frame", "Final_Frame (+KFF)",
     [](Text v, Text what, Text where, RaytraceOptions& o) {
         o.animation.final_frame = parse_frame(v, what, where);
     }},
    {"KI", "initial_clock", "Initial_Clock (+KI)",
     [](Text v, Text what, Text where, RaytraceOptions& o) {
         o.animation.initial_clock = parse_number(v, what, where);
     }},
    {"KF", "final_clock", "Final_Clock (+KF)",
     [](Text v, Text what, Text where, RaytraceOptions& o) {
         o.animation.final_clock = parse_number(v, what, where);
     }},
    {"K", "clock", "Clock (+K)",
     [](Text v, Text what, Text where, RaytraceOptions& o) {
         o.animation.clock = parse_number(v, what, where);
     }},
    {"SF", "subset_start_frame", "Subset_Start_Frame (+SF)",
     [](Text v, Text what, Text where, RaytraceOptions& o) {
         o.animation.subset_start = parse_number(v, what, where);
     }},
    {"EF", "subset_end_frame", "Subset_End_Frame (+EF)",
     [](Text v, Text what, Text where, RaytraceOptions& o) {
         o.animation.subset_end = parse_number(v, what, where);
     }},
    {"W", "width", "Width (+W)",
     [](Text v, Text what, Text where, RaytraceOptions& o) {
         o.width = parse_size(v, what, where);
     }},
    {"H", "height", "Height (+H)",
     [](Text v, Text what, Text where, RaytraceOptions& o) {
         o.height = parse_size(v, what, where);
     }},
    {"O", "output_file_name", "Output_File_Name (+O)",
     [](Text v, Text, Text, RaytraceOptions& o) { o.output = v; }},
    {"I", "input_file_name", "Input_File_Name (+I)",
     [](Text v, Text, Text, RaytraceOptions& o) { o.scene = v; }},
    {"L", "library_path", "Library_Path (+L)",
     [](Text v, Text, Text, RaytraceOptions& o) { o.include_paths.push_back(v); }},
};

constexpr const char* kSupportedSwitches = "+W +H +O +I +L +K +KFI +KFF +KI +KF +SF +EF";

// POV-Ray .ini options that tune its own sampling, bounding, quality, display, console and file
// output: they have nothing to act on in a progressive physical renderer, which always writes its
// image, so a POV-Ray .ini file may keep them (the sample scenes' .ini files carry them). They are
// read and have no effect.
const char* const kIniKeysWithoutEffect[] = {"antialias",
                                             "antialias_threshold",
                                             "antialias_depth",
                                             "antialias_gamma",
                                             "jitter",
                                             "jitter_amount",
                                             "sampling_method",
                                             "pause_when_done",
                                             "output_file_type",
                                             "output_alpha",
                                             "output_to_file",
                                             "bits_per_color",
                                             "test_abort",
                                             "test_abort_count",
                                             "verbose",
                                             "display",
                                             "display_gamma",
                                             "dither",
                                             "dither_method",
                                             "palette",
                                             "preview_start_size",
                                             "preview_end_size",
                                             "warning_console",
                                             "debug_console",
                                             "fatal_console",
                                             "render_console",
                                             "statistic_console",
                                             "all_console",
                                             "render_pattern",
                                             "render_block_size",
                                             "render_block_step",
                                             "draw_vistas",
                                             "all_file",
                                             "debug_file",
                                             "fatal_file",
                                             "render_file",
                                             "statistic_file",
                                             "warning_file",
                                             "create_ini",
                                             "quality",
                                             "bounding",
                                             "bounding_method",
                                             "bounding_threshold",
                                             "light_buffer",
                                             "vista_buffer",
                                             "remove_bounds",
                                             "split_unions",
                                             "high_reproducibility",
                                             "radiosity_vain_pretrace",
                                             "pre_scene_return",
                                             "pre_frame_return",
                                             "post_frame_return",
                                             "post_scene_return",
                                             "user_abort_return",
                                             "fatal_error_return"};

// Options that change what POV-Ray renders or does when they are on (interlaced fields, grey
// output, a continued or real-time render, radiosity data files): read when off, refused when on.
const char* const kIniKeysOnlyOff[] = {"field_render",        "odd_field",
                                       "grayscale_output",    "continue_trace",
                                       "clockless_animation", "real_time_raytracing",
                                       "radiosity_from_file", "radiosity_to_file"};

// Shell commands POV-Ray runs around a render and a header it includes before the scene: read
// when empty, refused otherwise (raytrace runs no commands and reads only the scene).
const char* const kIniKeysOnlyEmpty[] = {
    "pre_scene_command",  "pre_frame_command",   "post_frame_command", "post_scene_command",
    "user_abort_command", "fatal_error_command", "include_header"};

// The region to render, as a fraction (0 to 1) or a pixel number: only the whole image is read.
const char* const kIniRegionKeys[] = {"start_column", "end_column", "start_row", "end_row"};

template <size_t N>
bool one_of(const std::string& key, const char* const (&keys)[N]) {
    return std::find(std::begin(keys), std::end(keys), key) != std::end(keys);
}

// A boolean option's value as POV-Ray reads it: on/off, true/false, yes/no, 1/0.
bool ini_bool(const std::string& value, const std::string& name, const std::string& where) {
    const std::string v = lower(value);
    if (v == "on" || v == "true" || v == "yes" || v == "1") return true;
    if (v == "off" || v == "false" || v == "no" || v == "0") return false;
    throw Error(fmt::format("{}: {} must be on or off (or true/false, yes/no, 1/0), got '{}'",
                            where, name, value));
}

// Declare=NAME=VALUE: a float identifier the scene sees as declared (POV-Ray's option).
void apply_declaration(const std::string& text, const std::string& where, RaytraceOptions& o) {
    const auto equals = text.find('=');
    char* end = nullptr;
    const std::string value = equals == std::string::npos ? "" : text.substr(equals + 1);
    const double number = std::strtod(value.c_str(), &end);
    if (equals == std::string::npos || equals == 0 || value.empty() || *end != '\0')
        throw Error(fmt::format("{}: expected Declare=NAME=NUMBER, found Declare={}", where, text));
    o.declarations.emplace_back(text.substr(0, equals), number);
}
constexpr const char* kSupportedIniKeys =
    "Width, Height, Output_File_Name, Input_File_Name, Library_Path, Clock, Initial_Frame, "
    "Final_Frame, Initial_Clock, Final_Clock, Subset_Start_Frame, Subset_End_Frame";

// A subset bound: a value strictly between 0 and 1 is the frame int(value * frames) (POV-Ray 3.7:
// +SF0.35 of frames 1..10 is frame 3), anything else a frame number.
int subset_frame(double value, int frame_count) {
    return int(value > 0 && value < 1 ? std::floor(value * frame_count) : std::trunc(value));
}

std::string upper(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::toupper(c); });
    return s;
}

}  // namespace

void apply_pov_switch(const std::string& text, const std::string& where, RaytraceOptions& o) {
    const std::string name = upper(text);
    if (name == "+KC") {
        o.animation.cyclic = true;
        return;
    }
    if (name == "-KC") {
        o.animation.cyclic = false;
        return;
    }
    for (const PovSetting& setting : kPovSettings) {
        const size_t length = std::char_traits<char>::length(setting.switch_name);
        const bool named = text[0] == '+' && name.compare(1, length, setting.switch_name) == 0;
        if (!named || text.size() <= 1 + length) continue;
        setting.apply(text.substr(1 + length), setting.what, where, o);
        return;
    }
    throw Error(
        fmt::format("{}: POV-Ray switch '{}' is not supported (supported, each with a "
                    "value: {})",
                    where, text, kSupportedSwitches));
}

void apply_ini_file(const std::string& path, RaytraceOptions& o) {
    std::ifstream in(path);
    if (!in) throw Error(fmt::format("{}: cannot open the .ini file", path));
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::string where = fmt::format("{}:{}", path, number);
        line = trim(line.substr(0, line.find(';')));
        if (line.empty()) continue;
        if (line[0] == '+' || line[0] == '-') {
            // Switches, several to a line, and Key=Value among them (POV-Ray reads these too).
            std::istringstream words(line);
            for (std::string word; words >> word;) {
                if (word[0] == '+' || word[0] == '-')
                    apply_pov_switch(word, where, o);
                else
                    apply_ini_setting(word, where, o);
            }
            continue;
        }
        if (line[0] == '[')
            throw Error(fmt::format("{}: not supported: .ini sections ('{}')", where, line));
        apply_ini_setting(line, where, o);
    }
}

void apply_ini_setting(const std::string& line, const std::string& where, RaytraceOptions& o) {
    const auto equals = line.find('=');
    if (equals == std::string::npos)
        throw Error(fmt::format("{}: expected 'Key=Value' or a +switch, found '{}'", where, line));
    const std::string key = lower(trim(line.substr(0, equals)));
    std::string value = trim(line.substr(equals + 1));
    if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
        value = value.substr(1, value.size() - 2);
    const std::string name = trim(line.substr(0, equals));
    if (one_of(key, kIniKeysWithoutEffect)) return;
    if (one_of(key, kIniKeysOnlyOff)) {
        if (value.empty() || !ini_bool(value, name, where)) return;
        throw Error(fmt::format("{}: not supported: {}={} (only off)", where, name, value));
    }
    if (one_of(key, kIniKeysOnlyEmpty)) {
        if (value.empty()) return;
        throw Error(
            fmt::format("{}: not supported: {}={} (raytrace runs no commands and reads no "
                        "header: remove the option)",
                        where, name, value));
    }
    if (one_of(key, kIniRegionKeys)) {
        const bool start = key.rfind("start_", 0) == 0;
        char* end = nullptr;
        const double v = std::strtod(value.c_str(), &end);
        if (*end == '\0' && !value.empty() && (start ? v >= 0 && v <= 1 : v == 1)) return;
        throw Error(
            fmt::format("{}: not supported: {}={} (only the whole image: render it and crop)",
                        where, name, value));
    }
    if (key == "version") {
        if (value == "3.7" || value == "3.70") return;
        throw Error(fmt::format("{}: not supported: Version={} (the language of POV-Ray 3.7 only)",
                                where, value));
    }
    if (key == "cyclic_animation") {
        o.animation.cyclic = ini_bool(value, name, where);
        return;
    }
    if (key == "declare") return apply_declaration(value, where, o);
    const auto setting = std::find_if(std::begin(kPovSettings), std::end(kPovSettings),
                                      [&](const PovSetting& s) { return key == s.ini_key; });
    if (setting == std::end(kPovSettings))
        throw Error(
            fmt::format("{}: not supported: .ini option '{}' (supported: {}, Cyclic_Animation, "
                        "Declare; POV-Ray's antialiasing, bounding, quality, display, console and "
                        "output options are read and have no effect)",
                        where, name, kSupportedIniKeys));
    setting->apply(value, setting->what, where, o);
}

AnimationFrames animation_frames(const AnimationOptions& options, int width, int height) {
    AnimationFrames frames;
    AnimationSettings& first = frames.first;
    first.image_width = width;
    first.image_height = height;
    const int initial = std::max(options.initial_frame.value_or(1), 0);
    if (!options.final_frame || *options.final_frame <= initial) {
        first.clock = options.clock.value_or(0);
        first.clock_on = options.clock.has_value();
        return frames;
    }
    // A cyclic animation runs as if it had one frame more, which it does not render, so that its
    // last frame stops one step short of the final clock (POV-Ray reports that final frame too).
    const int rendered_final = *options.final_frame;
    const int final = rendered_final + (options.cyclic ? 1 : 0);
    first.clock_on = true;
    first.initial_frame = initial;
    first.final_frame = final;
    first.initial_clock = options.initial_clock.value_or(0);
    first.final_clock = options.final_clock.value_or(1);
    first.clock_delta = (first.final_clock - first.initial_clock) / (final - initial);
    const int count = rendered_final - initial + 1;
    const int start = options.subset_start ? subset_frame(*options.subset_start, count) : initial;
    const int end = options.subset_end ? subset_frame(*options.subset_end, count) : rendered_final;
    frames.first_frame = std::max(start, initial);  // never before the initial frame
    frames.last_frame = std::max(end, frames.first_frame);
    first.frame_number = frames.first_frame;
    first.clock = first.initial_clock + (frames.first_frame - initial) * first.clock_delta;
    return frames;
}

namespace {

// Options given on the command line, applied after .ini files and + switches (which they
// override).
struct CommandLine {
    std::string scene, output, png;
    std::vector<std::string> includes;
    int width = 0, height = 0, passes = 0, threads = 0;
    double time_limit = -1, exposure = 0;
    uint64_t seed = 0;
};

void add_image_options(CLI::App& app, RaytraceOptions& o, CommandLine& c) {
    app.add_option("scene", c.scene, "Scene file (.pov); or +Ifile / Input_File_Name=");
    app.add_option("-o,--output", c.output,
                   "Output OpenEXR file (default: SCENE-NAME.exr here); or +Ofile");
    app.add_option("--png", c.png, "Preview PNG file (default: the output's name with .png)");
    app.add_flag("--no-png", o.no_png, "Write no PNG preview");
    app.add_option("--width", c.width, "Image width in pixels (default 320); or +Wn")
        ->check(CLI::Range(1, kMaxImageSide));
    app.add_option("--height", c.height, "Image height in pixels (default 240); or +Hn")
        ->check(CLI::Range(1, kMaxImageSide));
    app.add_option("--passes", c.passes,
                   "Progressive passes (default: the scene's `passes`, else 16, "
                   "or unlimited with a time limit)")
        ->check(CLI::PositiveNumber);
    app.add_option("--time", c.time_limit,
                   "Time budget in seconds, checked between passes (default: the scene's "
                   "`time_limit`)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--threads", c.threads,
                   "Threads (default: every core); the image does not depend on it")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--seed", c.seed, "Random seed (default 0): same seed and passes, same image");
    app.add_option("--include-path", c.includes,
                   "Folder searched for #include and mesh files (repeatable); or +Ldir");
    app.add_option("--exposure", c.exposure,
                   "PNG preview: multiply radiance in W/(m^2 sr) by this before sRGB "
                   "(default: 1 / 99th percentile of the largest channel of the lit pixels)")
        ->check(CLI::PositiveNumber);
}

void add_tool_options(CLI::App& app, RaytraceOptions& o) {
    app.add_flag("--bench", o.bench,
                 "Benchmark: renderer rays/s against bare Embree rtcIntersect1 on the same "
                 "rays, 1 and 2 threads; writes nothing");
    app.add_flag("-q,--quiet", o.quiet, "No progress bar or summary");
    app.add_flag("--parse-only", o.parse_only,
                 "Read the scene (includes, macros, every statement) and say what it "
                 "holds or why it cannot be read; render nothing");
    app.add_option("--allow-write", o.write_roots,
                   "Folder the scene's #fopen ... write/append may write to, "
                   "relative names from the working directory (repeatable; "
                   "default: none, writing is refused)");
    app.add_option("--max-parse-memory", o.max_parse_memory_mb,
                   "Megabytes the scene may make the parser grow by "
                   "(default: half the RAM)")
        ->check(CLI::PositiveNumber);
    app.add_option("--max-objects", o.max_objects,
                   "Objects the scene may place (a union counts its parts, a mesh one; "
                   "default: " +
                       std::to_string(ParseOptions{}.max_objects) + ")")
        ->check(CLI::PositiveNumber);
    app.add_option("--max-lights", o.max_lights,
                   "Light sources the scene may place (default: " +
                       std::to_string(ParseOptions{}.max_lights) + ")")
        ->check(CLI::PositiveNumber);
}

void add_transport_options(CLI::App& app, RaytraceOptions& o) {
    app.add_option(
           "--photons", o.photons_per_pass,
           fmt::format("Bidirectional and vcm: photons (light subpaths) per pass (default: the "
                       "pass's camera samples, at least {}; a pass takes photons / (pixels + "
                       "receiver cells) samples per pixel and cell, at least 1)",
                       kMinimumLightPathsPerPass))
        ->check(CLI::PositiveNumber);
    app.add_option("--photon-radius", o.photon_radius,
                   "Bidirectional and vcm: gather radius of the first pass in scene "
                   "units (default: 1/100 of the extent of the first hits of the view and "
                   "the receiver cells)")
        ->check(CLI::PositiveNumber);
    app.add_flag("--naive-sources", o.naive_sources,
                 "Bidirectional: ray sources as their stored rays (the naive "
                 "model of the paper's Figure 1) instead of the light model");
    app.add_flag("--spectral", o.spectral,
                 "Spectral transport, either integrator (4 hero wavelengths per path "
                 "and photon, sources' spectra, RGB lights and materials upsampled) "
                 "instead of RGB; "
                 "also global_settings { spectral on }");
}

void add_checkpoint_options(CLI::App& app, RaytraceOptions& o) {
    app.add_flag("--resume", o.resume,
                 "Continue the interrupted render whose checkpoint is OUT.checkpoint (same "
                 "scene and options), up to --passes or --time in total");
    app.add_flag("--keep-checkpoint", o.keep_checkpoint,
                 "Keep OUT.checkpoint after the render completes (to "
                 "resume later with more passes)");
    app.add_option("--checkpoint-interval", o.checkpoint_interval,
                   "Seconds between checkpoints (default 10; 0: "
                   "after every pass)")
        ->check(CLI::NonNegativeNumber);
}

void apply_command_line(const CommandLine& c, RaytraceOptions& o) {
    if (!c.scene.empty()) o.scene = c.scene;
    if (!c.output.empty()) o.output = c.output;
    if (!c.png.empty()) o.png = c.png;
    if (c.width) o.width = c.width;
    if (c.height) o.height = c.height;
    if (c.passes) o.passes = c.passes;
    if (c.time_limit >= 0) o.time_limit = c.time_limit;
    o.threads = c.threads;
    o.seed = c.seed;
    o.exposure = c.exposure;
    o.include_paths.insert(o.include_paths.end(), c.includes.begin(), c.includes.end());
}

}  // namespace

bool parse_raytrace_options(int argc, char** argv, RaytraceOptions& o, int& exit_code) {
    std::vector<std::string> ini_files, pov_switches, rest;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg.size() > 1 && arg[0] == '+')
            pov_switches.push_back(arg);
        else if (lower(arg).rfind("declare=", 0) == 0)
            pov_switches.push_back(arg);
        else if (ends_with_ini(arg) && arg[0] != '-')
            ini_files.push_back(arg);
        else
            rest.push_back(arg);
    }
    CLI::App app(kDescription, "raytrace");
    app.get_formatter()->column_width(34);
    CommandLine command_line;
    add_image_options(app, o, command_line);
    add_tool_options(app, o);
    add_transport_options(app, o);
    add_checkpoint_options(app, o);
    try {
        std::reverse(rest.begin(), rest.end());  // CLI11 takes the arguments in reverse order
        app.parse(rest);
    } catch (const CLI::ParseError& e) {
        exit_code = app.exit(e) == 0 ? 0 : 2;  // --help, or a usage error
        return false;
    }
    for (const std::string& ini : ini_files) apply_ini_file(ini, o);
    for (const std::string& s : pov_switches) {
        if (s[0] == '+')
            apply_pov_switch(s, "command line", o);
        else
            apply_ini_setting(s, "command line", o);
    }
    apply_command_line(command_line, o);
    if (o.scene.empty()) {
        std::fprintf(stderr,
                     "raytrace: no scene file given (raytrace SCENE.pov, +ISCENE.pov or "
                     "Input_File_Name= in an "
                     ".ini file); see raytrace --help\n");
        exit_code = 2;
        return false;
    }
    return true;
}

}  // namespace rayset::tracer
