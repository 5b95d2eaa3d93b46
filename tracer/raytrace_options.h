// Command line of `raytrace`: our GNU-style options, POV-Ray's +W +H +O +I +L switches, its
// animation switches (+K +KFI +KFF +KI +KF +SF +EF) and POV-Ray .ini files (Width=, Height=,
// Output_File_Name=, Input_File_Name=, Library_Path=, Clock=, Initial_Frame=, Final_Frame=,
// Initial_Clock=, Final_Clock=, Subset_Start_Frame=, Subset_End_Frame=).
// Precedence: .ini files (in order), then + switches, then -- options.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer {

// POV-Ray's animation options as given; unset: not given.
struct AnimationOptions {
    std::optional<double> clock;                       // +K, Clock=
    std::optional<int> initial_frame, final_frame;     // +KFI +KFF, Initial_Frame= Final_Frame=
    std::optional<double> initial_clock, final_clock;  // +KI +KF, Initial_Clock= Final_Clock=
    // +SF +EF, Subset_Start_Frame= Subset_End_Frame=: a frame number, or a value strictly between
    // 0 and 1 for a fraction of the frames.
    std::optional<double> subset_start, subset_end;
    bool cyclic =
        false;  // +KC, Cyclic_Animation=on: the last frame stops one step short of the end
};

struct RaytraceOptions {
    std::string scene;
    std::string output;  // EXR path; default: the scene's name with .exr, in the current folder
    std::string png;     // preview path; default: the EXR's path with .png
    bool no_png = false;
    int width = 0, height = 0;  // 0: the renderer's default (320 x 240)
    int passes = 0;             // 0: the scene's `passes`, else the renderer's rule
    double time_limit = -1;     // < 0: the scene's `time_limit`
    int threads = 0;
    uint64_t seed = 0;
    double exposure = 0;
    std::vector<std::string> include_paths;
    bool bench = false;
    bool parse_only = false;               // read the scene, report what it holds, render nothing
    std::vector<std::string> write_roots;  // folders the scene's #fopen may write to
    std::vector<std::pair<std::string, double>> declarations;  // Declare=NAME=VALUE
    long max_parse_memory_mb = 0;  // 0: the parser's default (half the RAM)
    long max_objects = 0;          // 0: the parser's default
    long max_lights = 0;           // 0: the parser's default
    bool quiet = false;
    // Bidirectional integrator (global_settings { integrator "bidirectional" }).
    int photons_per_pass = 0;    // 0: the renderer's default
    double photon_radius = 0;    // scene units; 0: the renderer's default
    bool naive_sources = false;  // ray sources as their stored rays (paper Figure 1)
    bool spectral = false;       // spectral transport (bidirectional)
    // Stop and resume: OUT.checkpoint beside the output holds the last completed pass.
    bool resume = false;              // continue from OUT.checkpoint
    bool keep_checkpoint = false;     // keep OUT.checkpoint after a completed render
    double checkpoint_interval = 10;  // seconds between checkpoints; 0: after every pass
    AnimationOptions animation;
};

// The frames POV-Ray would render and the built-ins of the first of them.
struct AnimationFrames {
    AnimationSettings first;              // clock, frame_number, ..., image_width and image_height
    int first_frame = 0, last_frame = 0;  // equal: one frame (also without animation)
};

// As POV-Ray 3.7 computes them (checked against its runs): the animation is on when a final frame
// above the initial one is given (initial default 1, negative taken as 0); then clock_delta =
// (final_clock - initial_clock) / (final_frame - initial_frame) (clocks default 0 and 1), the
// subset starts at +SF (a fraction f in (0, 1) meaning frame int(f * frames); never before the
// initial frame) and ends at +EF (default: the final frame), and clock = initial_clock +
// (frame - initial_frame) * clock_delta. Off: clock is +K (0 when not given; clock_on says
// whether it was) and the frame values are 0. POV-Ray's own single-frame ranges (+KFI2 +KFF2)
// give a NaN clock; here they count as no animation.
AnimationFrames animation_frames(const AnimationOptions& options, int width, int height);

// Returns false when the program should exit with `exit_code` (help shown, or a usage error
// already reported on stderr). Throws rayset::Error for a bad .ini file (FILE:LINE: ...).
bool parse_raytrace_options(int argc, char** argv, RaytraceOptions& options, int& exit_code);

// Applies one POV-Ray switch ("+W640", "+Oout.exr"); throws rayset::Error naming `where`.
void apply_pov_switch(const std::string& text, const std::string& where, RaytraceOptions& options);
// Applies one .ini setting ("Width=640", "Declare=Fp=0") read at `where`.
void apply_ini_setting(const std::string& line, const std::string& where, RaytraceOptions& options);
// Reads a POV-Ray .ini file into `options`.
void apply_ini_file(const std::string& path, RaytraceOptions& options);

}  // namespace rayset::tracer
