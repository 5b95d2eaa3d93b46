// global_settings { }: every POV-Ray 3.7 key (the radiosity, photons and subsurface blocks with
// POV-Ray's checks) and our own keys. Several global_settings statements add up, a later value
// replacing an earlier one, as in POV-Ray.
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "tracer/scene_language/grammar.h"

namespace rayset::tracer {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A numeric key of a settings block: where its value goes and the range POV-Ray allows
// (`low_open`: the low end itself is refused). Whole numbers are truncated as POV-Ray does.
template <typename Settings>
struct NumberKey {
    Keyword keyword;
    double Settings::*real = nullptr;
    int Settings::*whole = nullptr;
    double low = -kInfinity;
    double high = kInfinity;
    bool low_open = false;
};

// A key whose boolean value must be written (`always_sample on`, not `always_sample`).
template <typename Settings>
struct BoolKey {
    Keyword keyword;
    bool Settings::*member;
};

std::string range_text(double low, double high, bool low_open) {
    if (high == kInfinity) return fmt::format("{} {}", low_open ? ">" : ">=", low);
    if (low == -kInfinity) return fmt::format("<= {}", high);
    return fmt::format("in {}{}, {}]", low_open ? "(" : "[", low, high);
}

// Reads the value of `key` (just taken as `token`) into `settings`, checking its range.
template <typename Settings>
void parse_number_key(Parser& p, const Token& token, const NumberKey<Settings>& key,
                      Settings& settings, const char* block) {
    const Token at = p.peek();
    const std::string& name = p.word(token);
    double value = p.parse_float(fmt::format("after '{}'", name));
    if (key.whole) value = std::trunc(value);
    const bool valid = (key.low_open ? value > key.low : value >= key.low) && value <= key.high;
    if (!valid)
        p.fail(at, fmt::format("{} {} must be {}, found {}", block, name,
                               range_text(key.low, key.high, key.low_open), value));
    if (key.whole && !(std::abs(value) < 2147483648.0))
        p.fail(at, fmt::format("{} {} must be a whole number of at most 10 digits, found {}", block,
                               name, value));
    if (key.whole)
        settings.*key.whole = static_cast<int>(value);
    else
        settings.*key.real = value;
}

// True when `token` is one of the keys of `numbers` (and its value was read).
template <typename Settings, size_t N>
bool parse_number_table_key(Parser& p, const Token& token, const NumberKey<Settings> (&numbers)[N],
                            Settings& settings, const char* block) {
    for (const NumberKey<Settings>& key : numbers)
        if (token.is(key.keyword)) {
            p.next();
            parse_number_key(p, token, key, settings, block);
            return true;
        }
    return false;
}

// True when `token` is one of the keys of `bools` (and its value was read).
template <typename Settings, size_t N>
bool parse_bool_table_key(Parser& p, const Token& token, const BoolKey<Settings> (&bools)[N],
                          Settings& settings) {
    for (const BoolKey<Settings>& key : bools)
        if (token.is(key.keyword)) {
            p.next();
            const std::string purpose = fmt::format("after '{}' (on or off)", p.word(token));
            settings.*key.member = p.parse_float(purpose) != 0;
            return true;
        }
    return false;
}

// `KEY first [,] [second]`: whether a second value follows.
bool second_value_follows(Parser& p) {
    return p.accept(Symbol::comma) || p.starts_expression(p.peek());
}

using Radiosity = RadiositySettings;
const NumberKey<Radiosity> kRadiosityNumbers[] = {
    {Keyword::adc_bailout, &Radiosity::adc_bailout},
    {Keyword::brightness, &Radiosity::brightness, nullptr, 0, kInfinity, true},
    {Keyword::error_bound, &Radiosity::error_bound, nullptr, 0, kInfinity, true},
    {Keyword::gray_threshold, &Radiosity::gray_threshold, nullptr, 0, 1},
    {Keyword::low_error_factor, &Radiosity::low_error_factor},
    {Keyword::max_sample, &Radiosity::max_sample},
    {Keyword::maximum_reuse, &Radiosity::maximum_reuse},
    {Keyword::minimum_reuse, &Radiosity::minimum_reuse},
    {Keyword::pretrace_start, &Radiosity::pretrace_start, nullptr, 0, 1, true},
    {Keyword::pretrace_end, &Radiosity::pretrace_end, nullptr, 0, 1, true},
    {Keyword::recursion_limit, nullptr, &Radiosity::recursion_limit, 1, 20},
};
const BoolKey<Radiosity> kRadiosityBools[] = {
    {Keyword::always_sample, &Radiosity::always_sample},
    {Keyword::normal, &Radiosity::normal},
    {Keyword::media, &Radiosity::media},
    {Keyword::subsurface, &Radiosity::subsurface},
};

// count N [, POOL]: the pool of directions holds at least N.
void parse_radiosity_count(Parser& p, Radiosity& r) {
    r.count = p.parse_int("after 'count'", 1);
    r.direction_pool = 0;
    if (!second_value_follows(p)) return;
    const Token at = p.peek();
    r.direction_pool = p.parse_int("as the direction pool of 'count'", 1);
    if (r.direction_pool < r.count)
        p.fail(at, fmt::format("radiosity count {} is larger than its direction pool {}", r.count,
                               r.direction_pool));
}

// nearest_count N [, ADAPTIVE]: N in 1..20, ADAPTIVE in [0, N).
void parse_radiosity_nearest_count(Parser& p, Radiosity& r) {
    const Token at = p.peek();
    const double nearest = std::trunc(p.parse_float("after 'nearest_count'"));
    if (!(nearest >= 1 && nearest <= 20))
        p.fail(at, fmt::format("radiosity nearest_count must be in [1, 20], found {}", nearest));
    r.nearest_count = static_cast<int>(nearest);
    r.adaptive_nearest_count = 0;
    if (!second_value_follows(p)) return;
    const Token adaptive_at = p.peek();
    const double adaptive = std::trunc(p.parse_float("as the adaptive value of 'nearest_count'"));
    if (!(adaptive >= 0 && adaptive < r.nearest_count))
        p.fail(adaptive_at, fmt::format("radiosity nearest_count's adaptive pretrace value must be "
                                        "in [0, {}), found {}",
                                        r.nearest_count, adaptive));
    r.adaptive_nearest_count = static_cast<int>(adaptive);
}

void parse_radiosity(Parser& p, const Token& keyword, GlobalSettings& g) {
    const Token open = p.expect_open(keyword);
    if (!g.radiosity) g.radiosity.emplace();
    Radiosity& r = *g.radiosity;
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (parse_number_table_key(p, token, kRadiosityNumbers, r, "radiosity") ||
            parse_bool_table_key(p, token, kRadiosityBools, r))
            continue;
        p.next();
        if (token.is(Keyword::count))
            parse_radiosity_count(p, r);
        else if (token.is(Keyword::nearest_count))
            parse_radiosity_nearest_count(p, r);
        else if (token.is(Keyword::save_file))
            r.save_file = p.parse_string();
        else if (token.is(Keyword::load_file))
            r.load_file = p.parse_string();
        else
            p.fail_identifier(token, fmt::format("a radiosity setting or '}}' to close 'radiosity' "
                                                 "opened at {}",
                                                 p.location_of(open).str()));
    }
    p.expect_close(keyword, open);
    // POV-Ray checks the pair once the block is read, whatever the order of the two keys.
    if (r.minimum_reuse >= r.maximum_reuse)
        p.fail(keyword, fmt::format("radiosity maximum_reuse {} must be larger than minimum_reuse "
                                    "{}",
                                    r.maximum_reuse, r.minimum_reuse));
    if (r.minimum_reuse > r.maximum_reuse / 2)
        p.warn(keyword, "radiosity maximum_reuse should be at least twice minimum_reuse");
}

// radius [R] [, M [, MEDIA_R [, MEDIA_M]]]: every value optional, a comma holding its place.
void parse_photon_radius(Parser& p, PhotonSettings& photons) {
    double* slots[] = {&photons.radius, &photons.radius_multiplier, &photons.media_radius,
                       &photons.media_radius_multiplier};
    for (double* slot : slots) {
        if (p.starts_expression(p.peek())) *slot = p.parse_float("in 'radius'");
        if (!p.accept(Symbol::comma)) return;
    }
}

// gather MIN, MAX and expand_thresholds INCREASE, MIN.
void parse_photon_pair(Parser& p, const Token& token, PhotonSettings& photons) {
    if (token.is(Keyword::expand_thresholds)) {
        photons.expand_increase = p.parse_float("after 'expand_thresholds'");
        p.accept_comma();
        photons.expand_min = p.parse_int("as the minimum of 'expand_thresholds'", 0);
        return;
    }
    const Token at = p.peek();
    photons.gather_min = p.parse_int("after 'gather'", 0);
    p.accept_comma();
    photons.gather_max = p.parse_int("as the maximum of 'gather'", 0);
    if (photons.gather_min >= photons.gather_max)
        p.fail(at, fmt::format("photons gather: the minimum {} must be less than the maximum {}",
                               photons.gather_min, photons.gather_max));
}

// One key of the photons block (just taken as `token`); false when it is none.
bool parse_photon_key(Parser& p, const Token& token, PhotonSettings& photons) {
    const std::string after = fmt::format("after '{}'", p.word(token));
    if (token.is(Keyword::spacing)) {
        photons.spacing = p.parse_float(after);
    } else if (token.is(Keyword::count)) {
        photons.count = p.parse_int(after, -2147483647);
    } else if (token.is(Keyword::gather) || token.is(Keyword::expand_thresholds)) {
        parse_photon_pair(p, token, photons);
    } else if (token.is(Keyword::media)) {
        photons.media_max_steps = p.parse_int(after, 0);
        if (second_value_follows(p))
            photons.media_factor = p.parse_float("as the factor of 'media'");
    } else if (token.is(Keyword::jitter)) {
        photons.jitter = p.parse_float(after);
    } else if (token.is(Keyword::max_trace_level)) {
        photons.max_trace_level = p.parse_int(after, 0);
    } else if (token.is(Keyword::adc_bailout)) {
        photons.adc_bailout = p.parse_float(after);
    } else if (token.is(Keyword::save_file)) {
        photons.save_file = p.parse_string();
    } else if (token.is(Keyword::load_file)) {
        photons.load_file = p.parse_string();
    } else if (token.is(Keyword::autostop)) {
        photons.autostop = p.parse_float(after);
    } else if (token.is(Keyword::radius)) {
        parse_photon_radius(p, photons);
    } else {
        return false;
    }
    return true;
}

void parse_photons(Parser& p, const Token& keyword, GlobalSettings& g) {
    const Token open = p.expect_open(keyword);
    if (!g.photons) g.photons.emplace();
    PhotonSettings& photons = *g.photons;
    while (!p.peek_is(Symbol::rbrace)) {
        const Token token = p.next();
        if (!parse_photon_key(p, token, photons))
            p.fail_identifier(token, fmt::format("a photons setting or '}}' to close 'photons' "
                                                 "opened at {}",
                                                 p.location_of(open).str()));
    }
    p.expect_close(keyword, open);
    if (!photons.save_file.empty() && !photons.load_file.empty()) {
        p.warn(keyword,
               "photons: both save_file and load_file given; the map is loaded (as "
               "POV-Ray does)");
        photons.save_file.clear();
    }
}

// subsurface { samples DIFFUSE, SINGLE  radiosity BOOL }
void parse_subsurface(Parser& p, const Token& keyword, GlobalSettings& g) {
    const Token open = p.expect_open(keyword);
    if (!g.subsurface) g.subsurface.emplace();
    SubsurfaceSettings& subsurface = *g.subsurface;
    while (!p.peek_is(Symbol::rbrace)) {
        const Token token = p.next();
        if (token.is(Keyword::samples)) {
            subsurface.diffuse_samples = p.parse_int("after 'samples'", 1);
            p.accept_comma();
            subsurface.single_samples = p.parse_int("as the second value of 'samples'", 1);
        } else if (token.is(Keyword::radiosity)) {
            subsurface.radiosity = p.parse_float("after 'radiosity' (on or off)") != 0;
        } else {
            p.fail_identifier(token, fmt::format("samples, radiosity or '}}' to close 'subsurface' "
                                                 "opened at {}",
                                                 p.location_of(open).str()));
        }
    }
    p.expect_close(keyword, open);
}

const NumberKey<GlobalSettings> kGlobalNumbers[] = {
    {Keyword::adc_bailout, &GlobalSettings::adc_bailout},
    {Keyword::max_intersections, nullptr, &GlobalSettings::max_intersections},
    {Keyword::max_trace_level, nullptr, &GlobalSettings::max_trace_level, 0},
    {Keyword::mm_per_unit, &GlobalSettings::mm_per_unit},
    {Keyword::number_of_waves, nullptr, &GlobalSettings::number_of_waves},
    {Keyword::noise_generator, nullptr, &GlobalSettings::noise_generator, 1, 3},
};

// assumed_gamma G | srgb
void parse_assumed_gamma(Parser& p, const Token& keyword, GlobalSettings& g) {
    g.assumed_gamma_set = true;
    g.assumed_gamma_location = p.location_of(keyword);
    g.assumed_gamma_srgb = p.accept(Keyword::srgb);
    if (g.assumed_gamma_srgb) return;
    const Token at = p.peek();
    g.assumed_gamma = p.parse_float("after 'assumed_gamma'");
    if (!(g.assumed_gamma > 0))
        p.fail(at, fmt::format("assumed_gamma must be positive, found {}", g.assumed_gamma));
}

// charset ascii | utf8 | sys
void parse_charset(Parser& p, GlobalSettings& g) {
    const Token name = p.next();
    if (name.is(Keyword::ascii))
        g.charset = Charset::ascii;
    else if (name.is(Keyword::utf8))
        g.charset = Charset::utf8;
    else if (name.is(Keyword::sys))
        g.charset = Charset::sys;
    else
        p.fail_expected("ascii, utf8 or sys after 'charset'", name);
}

// POV-Ray's keys that are not plain numbers (`token` just taken); false for anything else.
bool parse_pov_key(Parser& p, const Token& token, GlobalSettings& g) {
    if (token.is(Keyword::assumed_gamma)) {
        parse_assumed_gamma(p, token, g);
    } else if (token.is(Keyword::charset)) {
        parse_charset(p, g);
    } else if (token.is(Keyword::ambient_light)) {
        g.ambient_light = p.parse_colour().rgb();
    } else if (token.is(Keyword::irid_wavelength)) {
        g.irid_wavelength = p.parse_colour().rgb();
    } else if (token.is(Keyword::hf_gray_16)) {
        p.parse_optional_bool();
        p.warn(token, "hf_gray_16 is deprecated in POV-Ray 3.7 and has no effect");
    } else if (token.is(Keyword::radiosity)) {
        parse_radiosity(p, token, g);
    } else if (token.is(Keyword::photons)) {
        parse_photons(p, token, g);
    } else if (token.is(Keyword::subsurface)) {
        parse_subsurface(p, token, g);
    } else {
        return false;
    }
    return true;
}

// length_unit "UNIT": the scene's unit and millimetres per unit.
void parse_length_unit(Parser& p, GlobalSettings& g) {
    static const std::pair<const char*, double> units[] = {
        {"um", 1e-3}, {"mm", 1.0}, {"cm", 10.0}, {"m", 1000.0}, {"in", 25.4}, {"ft", 304.8}};
    const Token at = p.peek();
    const std::string unit = p.parse_string();
    for (const auto& [name, mm] : units)
        if (unit == name) {
            g.length_unit = unit;
            g.millimetres_per_unit = mm;
            return;
        }
    p.fail(at, fmt::format("unknown length_unit \"{}\" (expected um, mm, cm, m, in or ft)", unit));
}

// Our keys: length_unit, integrator, spectral, passes, time_limit (`token` just taken).
bool parse_own_key(Parser& p, const Token& token, GlobalSettings& g) {
    if (token.is(ContextWord::length_unit)) {
        parse_length_unit(p, g);
    } else if (token.is(ContextWord::integrator)) {
        const Token at = p.peek();
        const std::string name = p.parse_string();
        if (std::find(kIntegratorNames.begin(), kIntegratorNames.end(), name) ==
            kIntegratorNames.end())
            p.fail(at, fmt::format("unknown integrator \"{}\" (expected {})", name,
                                   integrator_names_text()));
        g.integrator = name;
    } else if (token.is(ContextWord::spectral)) {
        g.spectral = p.parse_float("after 'spectral' (on or off)") != 0;
    } else if (token.is(ContextWord::passes)) {
        g.passes = p.parse_int("after 'passes'", 1);
    } else if (token.is(ContextWord::time_limit)) {
        const Token at = p.peek();
        g.time_limit = p.parse_float("after 'time_limit' (seconds)");
        if (!(g.time_limit > 0)) p.fail(at, "time_limit must be positive (seconds)");
    } else {
        return false;
    }
    return true;
}

}  // namespace

void parse_global_settings(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    GlobalSettings& g = p.scene().global;
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (parse_number_table_key(p, token, kGlobalNumbers, g, "global_settings")) continue;
        p.next();
        if (!parse_pov_key(p, token, g) && !parse_own_key(p, token, g))
            p.fail_identifier(token, fmt::format("a global setting or '}}' to close "
                                                 "'global_settings' opened at {}",
                                                 p.location_of(open).str()));
    }
    p.expect_close(keyword, open);
}

}  // namespace rayset::tracer
