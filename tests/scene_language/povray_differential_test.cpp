// The scene language against POV-Ray itself: each file in povray/ prints values with #debug
// (expressions, strings, random sequences, macros and directives, arrays, splines, functions,
// the macros of the standard include files); POV-Ray 3.7 (Debian's `povray`) and our parser
// read it, and every line must agree: the same text, and every number equal to the precision
// POV-Ray printed it with (one unit in the last printed digit, for a rounding that falls the
// other way). Skips, saying so, when povray is not installed.
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "support/test_support.h"
#include "tracer/scene_language/parse_error.h"
#include "tracer/scene_language/scene_language.h"

namespace rayset::tracer {
namespace {

namespace fs = std::filesystem;

const fs::path kSnippets = fs::path(RAYSET_SOURCE_DIR) / "tests" / "scene_language" / "povray";

bool povray_installed() { return std::system("command -v povray > /dev/null 2>&1") == 0; }

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// POV-Ray's debug stream for `scene`, parsed and rendered at 1 x 1 pixel in a scratch folder
// (POV-Ray writes its streams beside its image).
std::string povray_output(const fs::path& scene) {
    test::ScratchDir dir;
    const std::string command = "cd '" + dir.path().string() + "' && povray +I'" + scene.string() +
                                "' +W1 +H1 -D -V +Oout.png +GDdebug.txt -GR -GS > povray.log 2>&1";
    if (std::system(command.c_str()) != 0)
        ADD_FAILURE() << "povray failed on " << scene << ":\n"
                      << read_text(dir.path() / "povray.log");
    return read_text(dir.path() / "debug.txt");
}

// Our parser's debug text for `scene`, run like POV-Ray in a scratch folder it may write to.
std::string our_output(const fs::path& scene) {
    test::ScratchDir dir;
    const fs::path previous = fs::current_path();
    fs::current_path(dir.path());
    std::string debug;
    ParseOptions options;
    options.write_roots = {dir.path().string()};
    options.on_message = [&](MessageStream stream, const std::string& text) {
        if (stream == MessageStream::debug) debug += text;
    };
    try {
        parse_scene_file(scene.string(), options);
    } catch (const Error& e) {
        ADD_FAILURE() << "our parser failed on " << scene << ": " << e.what();
    }
    fs::current_path(previous);
    return debug;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// The line with its numbers replaced by '#', and the numbers as printed.
struct Printed {
    std::string text;
    std::vector<std::string> numbers;
};

Printed split_numbers(const std::string& line) {
    static const std::regex number(R"([-+]?\d+(\.\d+)?(e[-+]\d+)?)");
    Printed out;
    std::string rest = line;
    std::smatch match;
    while (std::regex_search(rest, match, number)) {
        out.text += match.prefix().str() + "#";
        out.numbers.push_back(match.str());
        rest = match.suffix().str();
    }
    out.text += rest;
    return out;
}

// Equal to POV-Ray's printed precision: within one unit of its last printed digit.
bool same_number(const std::string& ours, const std::string& theirs) {
    if (ours == theirs) return true;
    const size_t dot = theirs.find('.');
    const size_t exponent = theirs.find('e');
    const size_t end = exponent == std::string::npos ? theirs.size() : exponent;
    const int decimals = dot == std::string::npos ? 0 : static_cast<int>(end - dot - 1);
    double unit = std::pow(10.0, -decimals);
    if (exponent != std::string::npos)
        unit *= std::pow(10.0, std::stod(theirs.substr(exponent + 1)));
    return std::fabs(std::stod(ours) - std::stod(theirs)) <= 1.0001 * unit;
}

void expect_same_output(const std::string& file) {
    const fs::path scene = kSnippets / file;
    const std::vector<std::string> theirs = lines_of(povray_output(scene));
    const std::vector<std::string> ours = lines_of(our_output(scene));
    ASSERT_FALSE(theirs.empty()) << "POV-Ray printed nothing for " << file;
    EXPECT_EQ(ours.size(), theirs.size()) << file << ": line counts differ";
    int compared_numbers = 0;
    for (size_t i = 0; i < std::min(ours.size(), theirs.size()); ++i) {
        // POV-Ray wraps debug lines at 80 columns: the snippets keep theirs shorter.
        ASSERT_LT(theirs[i].size(), 79u) << file << " line " << i + 1 << " is too long to compare";
        const Printed a = split_numbers(ours[i]), b = split_numbers(theirs[i]);
        EXPECT_EQ(a.text, b.text) << file << " line " << i + 1 << "\n ours:    " << ours[i]
                                  << "\n POV-Ray: " << theirs[i];
        if (a.text != b.text || a.numbers.size() != b.numbers.size()) continue;
        for (size_t k = 0; k < a.numbers.size(); ++k, ++compared_numbers)
            EXPECT_TRUE(same_number(a.numbers[k], b.numbers[k]))
                << file << " line " << i + 1 << " number " << k + 1 << "\n ours:    " << ours[i]
                << "\n POV-Ray: " << theirs[i];
    }
    std::printf("%s: %zu lines, %d numbers agree with POV-Ray\n", file.c_str(), theirs.size(),
                compared_numbers);
}

class PovRayDifferential : public ::testing::TestWithParam<const char*> {
protected:
    void SetUp() override {
        if (!povray_installed())
            GTEST_SKIP() << "povray is not installed (scripts/install-deps.sh installs it)";
    }
};

TEST_P(PovRayDifferential, DebugOutputAgrees) { expect_same_output(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Snippets, PovRayDifferential,
                         ::testing::Values("expressions.pov", "strings.pov", "random.pov",
                                           "directives.pov", "arrays.pov", "splines.pov",
                                           "functions.pov", "includes.pov", "fileio.pov",
                                           "patterns.pov", "geometry.pov"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                             std::string name = info.param;
                             return name.substr(0, name.find('.'));
                         });

// The noise patterns cannot agree with POV-Ray's point for point (its lattice tables are its
// own, noise.h): they must agree in distribution and spectrum. Both read one scene that prints
// the pattern at 6000 random points (uniform in a 100-unit cube, seed 7) and at 0.1, 0.25, 0.5
// and 1 unit away in a random direction; mean, standard deviation and the correlation at each
// distance (the spectrum's Fourier pair) must agree. At 6000 points the difference of two
// independent estimates has a standard deviation below 0.0062 for a mean (agate's spread, 0.34)
// and below 0.018 for a correlation ((1 - rho^2) / sqrt(n), twice); the bounds are 2.4 and 2.7
// of those (mean 0.015, correlation 0.05). The spread's bound, 8%, is not statistical (its
// sampling error is 1.3%): it is the model's own error, the spreads of granite and of turbulent
// bozo being 5% and 4% from POV-Ray's.
struct Statistics {
    double mean = 0, deviation = 0;
    double correlation[4] = {0, 0, 0, 0};
};

Statistics statistics_of(const std::string& debug) {
    std::vector<std::array<double, 5>> rows;
    std::istringstream in(debug);
    for (std::array<double, 5> row; in >> row[0] >> row[1] >> row[2] >> row[3] >> row[4];)
        rows.push_back(row);
    Statistics s;
    if (rows.size() < 2) return s;
    const double n = static_cast<double>(rows.size());
    double mean[5] = {0, 0, 0, 0, 0};
    for (const auto& row : rows)
        for (int k = 0; k < 5; ++k) mean[k] += row[k] / n;
    double variance[5] = {0, 0, 0, 0, 0}, covariance[5] = {0, 0, 0, 0, 0};
    for (const auto& row : rows)
        for (int k = 0; k < 5; ++k) {
            variance[k] += (row[k] - mean[k]) * (row[k] - mean[k]) / n;
            covariance[k] += (row[0] - mean[0]) * (row[k] - mean[k]) / n;
        }
    s.mean = mean[0];
    s.deviation = std::sqrt(variance[0]);
    for (int k = 1; k < 5; ++k)
        s.correlation[k - 1] = covariance[k] / std::sqrt(variance[0] * variance[k]);
    return s;
}

std::string noise_probe(const std::string& pattern) {
    return "#version 3.7;\n"
           "#include \"functions.inc\"\n"
           "#declare F = function { pattern { " +
           pattern +
           " } }\n"
           "#declare S = seed(7);\n"
           "#declare Distances = array[4] {0.1, 0.25, 0.5, 1};\n"
           "#for (I, 1, 6000)\n"
           "  #declare P = <rand(S), rand(S), rand(S)> * 100 - 50;\n"
           "  #declare D = vnormalize(<rand(S), rand(S), rand(S)> - 0.5);\n"
           "  #debug concat(str(F(P.x, P.y, P.z), 0, 5))\n"
           "  #for (L, 1, 4)\n"
           "    #declare Q = P + Distances[L - 1] * D;\n"
           "    #debug concat(\" \", str(F(Q.x, Q.y, Q.z), 0, 5))\n"
           "  #end\n"
           "  #debug \"\\n\"\n"
           "#end\n";
}

class PovRayNoise : public PovRayDifferential {};

TEST_P(PovRayNoise, AgreesInDistributionAndSpectrum) {
    test::ScratchDir dir;
    const fs::path scene = dir.path() / "noise.pov";
    std::ofstream(scene) << noise_probe(GetParam());
    const Statistics theirs = statistics_of(povray_output(scene));
    const Statistics ours = statistics_of(our_output(scene));
    ASSERT_GT(theirs.deviation, 0) << "POV-Ray printed no values";
    EXPECT_NEAR(ours.mean, theirs.mean, 0.015);
    EXPECT_NEAR(ours.deviation, theirs.deviation, 0.08 * theirs.deviation);
    for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(ours.correlation[k], theirs.correlation[k], 0.05) << "distance " << k + 1;
    std::printf(
        "%-32s mean %.4f / %.4f  sd %.4f / %.4f  correlation %.3f %.3f %.3f %.3f / "
        "%.3f %.3f %.3f %.3f (ours / POV-Ray)\n",
        GetParam(), ours.mean, theirs.mean, ours.deviation, theirs.deviation, ours.correlation[0],
        ours.correlation[1], ours.correlation[2], ours.correlation[3], theirs.correlation[0],
        theirs.correlation[1], theirs.correlation[2], theirs.correlation[3]);
}

INSTANTIATE_TEST_SUITE_P(Patterns, PovRayNoise,
                         ::testing::Values("bozo", "bozo noise_generator 1",
                                           "bozo noise_generator 3", "spotted scale 0.3", "granite",
                                           "wrinkles", "dents", "agate", "agate agate_turb 0.5",
                                           "bozo turbulence 0.5", "marble turbulence 0.5",
                                           "wood turbulence 0.3", "wood turbulence <0.3, 0, 0>",
                                           "gradient x warp { turbulence 0.4 octaves 3 }",
                                           "crackle", "crackle metric 1",
                                           "crackle form <0, 1, 0> offset 0.5", "crackle solid",
                                           "function { f_noise3d(x, y, z) }",
                                           "function { f_noise_generator(x, y, z, 3) }"));

}  // namespace
}  // namespace rayset::tracer
