// The render whose checkpoints fuzz_checkpoint reads and fuzz_checkpoint_seed writes: a 3 x 2
// pixel image, one illuminance receiver of 2 x 2 cells and the bidirectional integrator's three
// light layers, so that every part of the file format is there.
#pragma once

#include "tracer/film/checkpoint.h"

namespace rayset::fuzz {

inline tracer::CheckpointIdentity checkpoint_identity() {
    tracer::CheckpointIdentity identity;
    identity.scene = "scene.pov";
    identity.scene_hash = 0x5eed;
    identity.width = 3, identity.height = 2;
    identity.seed = 1;
    identity.integrator = "bidirectional";
    identity.photons_per_pass = 1000;
    return identity;
}

// The state before the first pass, laid out as blank_render() lays out this render.
inline tracer::RenderResult blank_checkpoint_render() {
    tracer::IlluminanceReceiver receiver;
    receiver.name = "floor";
    receiver.nx = 2, receiver.ny = 2;
    tracer::RenderResult state;
    state.film = tracer::Film(3, 2);
    state.receivers.emplace_back(receiver);
    for (const char* layer : {"direct_visibility", "primary", "secondary"}) {
        state.layers.push_back({layer, tracer::Film(3, 2), {}});
        state.layers.back().receivers.emplace_back(receiver);
    }
    return state;
}

}  // namespace rayset::fuzz
