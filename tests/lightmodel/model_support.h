// Shared by the light-model, view and tracer tests: synthetic ray files from the analytic sources
// and models built from them once per build of the tests.
#pragma once

#include "converters/analytic/analytic_sources.h"
#include "lightmodel/complex_source.h"
#include "lightmodel/model_build.h"
#include "support/test_support.h"

#include <map>
#include <memory>
#include <string>

namespace rayset::test {

// A ray file synthesised from an analytic source and the model built from it with the default
// options, made once for all the test processes of one build: a model of 10^6 rays takes 15 s to
// build and many tests render the same one, each in its own process. The files are kept in the
// build tree (test-cache/<test binary>/<its size and time>/) and made again when the test binary
// changes; a lock makes concurrent processes wait for the one that makes them. The copies of
// both placed in `folder` as key.tm25ray and key.vdb are returned, so that a scene there may
// name them. `key` names the source uniquely within one test binary.
struct ModelFiles {
    std::string rays, model;
};
ModelFiles synthesised_model(const std::string& folder, const std::string& key,
                             const analytic::Source& source, uint64_t rays, uint64_t seed);

struct BuiltSource {
    std::unique_ptr<analytic::Source> truth;
    std::string ray_file;
    double ray_flux = 0;  // sum of the rays' radiant flux as the reader hands them out
    std::shared_ptr<const lightmodel::LightModel> model;
    std::unique_ptr<lightmodel::ComplexSource> source;
};

// "disk" (radius 1 mm), "sphere" (radius 1 mm), "lobe" (cos^4), "cluster" (the 39 chips);
// 1 W, 1e6 rays, seed 7; "disk4m": the disk from 4e6 rays. Its model is the one its file holds
// (synthesised_model), read on first use and kept for the whole test binary.
const BuiltSource& built_source(const std::string& name);

}  // namespace rayset::test
