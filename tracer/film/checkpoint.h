// Checkpoints of a progressive render: everything a render has accumulated after its last
// completed pass, so that a stopped render continues to the very bits an uninterrupted one
// ends with (every pixel's random stream depends on the seed and the pass only).
//
// File format, version 1, little-endian (u32/u64 integers, f64 IEEE doubles, strings as a u32
// byte count then the bytes):
//   "RAYSETCK" (8 bytes), u32 version
//   identity: str scene path, u64 scene hash, u32 width, u32 height, u64 seed, str integrator,
//             u8 render_image, u32 photons_per_pass, f64 photon_radius, u8 naive_sources
//   state:    u32 passes, f64 seconds, u64 rays, u64 photons, f64 photon_radius,
//             u64 photon_bytes, u64 visible_point_bytes
//   grids:    the film, u32 receiver count and per receiver str name + grid; u32 layer count and
//             per layer str name, film, receivers as before
//             (grid: u32 nx, u32 ny, u32 samples, nx*ny RGB sums as 3 f64, nx*ny f64 squares)
//   u64 FNV-1a hash of every byte before it
// Written through StagedFiles (temporary file, flushed to disk, renamed into place), so the
// file on disk is always a complete checkpoint, whenever the process is killed.
#pragma once

#include <cstdint>
#include <string>

#include "tracer/render/renderer.h"

namespace rayset::tracer {

inline constexpr uint32_t kCheckpointVersion = 1;

// What a checkpoint must agree on with the render that continues it.
struct CheckpointIdentity {
    std::string scene;        // the scene file, as the parser resolved it (informative)
    uint64_t scene_hash = 0;  // scene_content_hash()
    int width = 0, height = 0;
    uint64_t seed = 0;
    std::string integrator;  // "bidirectional spectral" with --spectral
    bool render_image = true;
    int photons_per_pass = 0;  // as set: 0 is the renderer's default
    double photon_radius = 0;  // as set
    bool naive_sources = false;
};

// FNV-1a over the text of every file the scene read (main file and #includes) and the path
// and size of each data file it names (mesh_file, ray_source): an edited scene no longer
// matches its checkpoint. Throws rayset::Error when a file cannot be read.
uint64_t scene_content_hash(const SceneDescription& scene);
CheckpointIdentity checkpoint_identity(const SceneDescription& scene,
                                       const RenderSettings& settings);

void write_checkpoint(const std::string& path, const CheckpointIdentity& identity,
                      const RenderResult& state);

// The state stored in `path`, laid out as `blank` (blank_render of the same scene and
// settings). Throws rayset::Error, with a message naming the file and what is wrong (not a
// checkpoint, another format version, truncated or corrupt, or each identity field that
// differs from `expected`), and changes no file.
RenderResult read_checkpoint(const std::string& path, const CheckpointIdentity& expected,
                             RenderResult blank);

}  // namespace rayset::tracer
