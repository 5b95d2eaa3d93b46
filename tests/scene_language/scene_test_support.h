// What the scene-language tests share: a text parsed as the file test.pov, the error or the
// warnings it gives, and a vector compared term by term.
#pragma once

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tracer/scene_language/parse_error.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer::scene_test {

inline SceneDescription parse(const std::string& text, const ParseOptions& options = {}) {
    return parse_scene_text(text, "test.pov", options);
}

// The message of the error a text gives, or "no error".
inline std::string error_of(const std::string& text, const ParseOptions& options = {}) {
    try {
        parse(text, options);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "no error";
}

// The message of the error a file gives, or "no error".
inline std::string error_of_file(const std::string& path, const ParseOptions& options = {}) {
    try {
        parse_scene_file(path, options);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "no error";
}

// The warnings a text gives.
inline std::vector<std::string> warnings_of(const std::string& text) {
    std::vector<std::string> warnings;
    ParseOptions options;
    options.on_message = [&](MessageStream stream, const std::string& message) {
        if (stream == MessageStream::warning) warnings.push_back(message);
    };
    parse(text, options);
    return warnings;
}

inline void expect_vec(Vec3 actual, Vec3 expected, double tolerance = 1e-12) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

}  // namespace rayset::tracer::scene_test
