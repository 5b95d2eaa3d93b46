// Shared by the light-model tests: synthetic ray files from the analytic sources and models
// built from them once per test binary (a build of a million rays takes seconds).
#pragma once

#include "converters/analytic/analytic_sources.h"
#include "lightmodel/complex_source.h"
#include "lightmodel/model_build.h"
#include "support/test_support.h"

#include <map>
#include <memory>
#include <string>

namespace rayset::test {

struct BuiltSource {
    std::unique_ptr<analytic::Source> truth;
    std::string ray_file;
    double ray_flux = 0;  // sum of the rays' radiant flux as the reader hands them out
    std::shared_ptr<const lightmodel::LightModel> model;
    std::unique_ptr<lightmodel::ComplexSource> source;
};

// "disk" (radius 1 mm), "sphere" (radius 1 mm), "lobe" (cos^4), "cluster" (the 39 chips);
// 1 W, 1e6 rays, seed 7; "disk4m": the disk from 4e6 rays. Built on first use and kept for the
// whole test binary.
const BuiltSource& built_source(const std::string& name);

}  // namespace rayset::test
