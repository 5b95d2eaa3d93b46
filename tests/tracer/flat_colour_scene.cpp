#include "tracer/flat_colour_scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "support/test_support.h"
#include "tracer/render/render_scene.h"
#include "tracer/render/renderer.h"
#include "tracer/scene_language/scene_language.h"
#include "tracer/tracer_support.h"

namespace rayset::test {
namespace {

namespace fs = std::filesystem;

// The object statements that take a texture.
const std::set<std::string> kObjects = {
    "bicubic_patch", "blob",         "box",          "cone",
    "cubic",         "cylinder",     "difference",   "disc",
    "height_field",  "intersection", "isosurface",   "julia_fractal",
    "lathe",         "lemon",        "merge",        "mesh",
    "mesh2",         "object",       "ovus",         "parametric",
    "plane",         "poly",         "polygon",      "polynomial",
    "prism",         "quadric",      "quartic",      "smooth_triangle",
    "sor",           "sphere",       "sphere_sweep", "superellipsoid",
    "text",          "torus",        "triangle",     "union"};
// Blocks removed where they are given (not where they are declared).
const std::set<std::string> kRemoved = {
    "texture",      "pigment",          "finish",       "normal",         "material",
    "interior",     "interior_texture", "texture_list", "photons",        "radiosity",
    "light_source", "light_group",      "fog",          "atmosphere",     "media",
    "sky_sphere",   "background",       "rainbow",      "global_settings"};
// Blocks copied as they are wherever they appear: their entries are textures and pigments.
const std::set<std::string> kKept = {"texture_map", "pigment_map", "normal_map", "material_map",
                                     "slope_map",   "color_map",   "colour_map", "function"};

struct Token {
    enum Kind { word, directive, string, other } kind;
    size_t begin, end;  // byte range in the text
    std::string text;   // the word, the directive's name, the string's contents, the character
};

// POV-Ray's tokens as far as the rewriting needs them: words, directives (#name), strings,
// single characters; comments (block comments nest; a line comment inside one ends at its line)
// and numbers skipped or kept as `other`.
class Tokens {
public:
    explicit Tokens(const std::string& text) : text_(text) {
        while (skip_space_and_comments(), pos_ < text_.size()) read();
    }
    const std::vector<Token>& all() const { return tokens_; }

private:
    char peek(size_t ahead = 0) const {
        return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0';
    }
    void skip_line() {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    }
    void skip_block_comment() {  // after its "/*"
        while (pos_ < text_.size()) {
            const char c = text_[pos_++];
            if (c == '*' && peek() == '/') {
                ++pos_;
                return;
            }
            if (c == '/' && peek() == '*')
                ++pos_, skip_block_comment();
            else if (c == '/' && peek() == '/')
                skip_line();
        }
    }
    void skip_space_and_comments() {
        for (;;) {
            if (pos_ >= text_.size()) return;
            const char c = peek();
            if (std::isspace(static_cast<unsigned char>(c)) || c == '\x1a')
                ++pos_;
            else if (c == '/' && peek(1) == '/')
                skip_line();
            else if (c == '/' && peek(1) == '*')
                pos_ += 2, skip_block_comment();
            else
                return;
        }
    }
    static bool is_word_char(char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    }
    std::string read_word() {
        const size_t start = pos_;
        while (pos_ < text_.size() && is_word_char(text_[pos_])) ++pos_;
        return text_.substr(start, pos_ - start);
    }
    void read() {
        const size_t begin = pos_;
        const char c = peek();
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            const std::string w = read_word();
            tokens_.push_back({Token::word, begin, pos_, w});
        } else if (c == '#') {
            ++pos_;
            while (peek() == ' ' || peek() == '\t') ++pos_;
            const std::string w = read_word();
            tokens_.push_back({Token::directive, begin, pos_, w});
        } else if (c == '"') {
            ++pos_;
            std::string s;
            while (pos_ < text_.size() && text_[pos_] != '"') {
                if (text_[pos_] == '\\' && pos_ + 1 < text_.size()) s += text_[pos_++];
                s += text_[pos_++];
            }
            ++pos_;
            tokens_.push_back({Token::string, begin, pos_, s});
        } else if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
            while (is_word_char(peek()) || peek() == '.' ||
                   ((peek() == '+' || peek() == '-') && (text_[pos_ - 1] | 0x20) == 'e'))
                ++pos_;
            tokens_.push_back({Token::other, begin, pos_, text_.substr(begin, pos_ - begin)});
        } else {
            ++pos_;
            tokens_.push_back({Token::other, begin, pos_, std::string(1, c)});
        }
    }

    const std::string& text_;
    size_t pos_ = 0;
    std::vector<Token> tokens_;
};

bool is(const std::vector<Token>& t, size_t i, const char* text) {
    return i < t.size() && t[i].kind == Token::other && t[i].text == text;
}

// The index of the '}' closing the '{' at `open` (the last token when it is never closed).
size_t closing(const std::vector<Token>& t, size_t open) {
    int depth = 0;
    for (size_t i = open; i < t.size(); ++i) {
        if (is(t, i, "{")) ++depth;
        if (is(t, i, "}") && --depth == 0) return i;
    }
    return t.size() - 1;
}

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::string colour_texture(int index) {
    const Rgb c = flat_colour(index);
    char text[160];
    std::snprintf(text, sizeof text,
                  " texture { pigment { rgb <%.9g, %.9g, %.9g> } "
                  "finish { emission 1 ambient 0 diffuse 0 } } ",
                  c.red, c.green, c.blue);
    return text;
}

// An insertion or a removal in a file's text: [begin, end) replaced by `insert`.
struct Edit {
    size_t begin, end;
    std::string insert;
};

// `text` with `edits` applied (at most one removal covers any character).
std::string apply_edits(const std::string& text, std::vector<Edit> edits) {
    std::string out;
    size_t at = 0;
    std::stable_sort(edits.begin(), edits.end(),
                     [](const Edit& a, const Edit& b) { return a.begin < b.begin; });
    for (const Edit& e : edits) {
        out.append(text, at, e.begin - at);
        out += e.insert;
        at = std::max(at, e.end);
    }
    out.append(text, at, std::string::npos);
    return out;
}

// The index of the brace after `array [...]...` (t[i] the word `array`).
size_t array_brace_after(const std::vector<Token>& t, size_t i) {
    size_t j = i + 1;
    while (is(t, j, "[")) {
        for (int depth = 0; j < t.size(); ++j) {
            depth += is(t, j, "[") - is(t, j, "]");
            if (depth == 0) break;
        }
        ++j;
    }
    return j;
}

class Rewriter {
public:
    Rewriter(fs::path source_folder, fs::path target_folder)
        : source_(std::move(source_folder)), target_(std::move(target_folder)) {}

    // Writes the rewritten copy of `relative` (a path under the source folder).
    void rewrite(const fs::path& relative, bool main_file) {
        if (!done_.insert(relative.lexically_normal().string()).second) return;
        const std::string text = read_text(source_ / relative);
        const std::vector<Token> t = Tokens(text).all();
        Scan scan;
        for (size_t i = 0; i < t.size(); ++i) {
            if (t[i].kind == Token::word) {
                copy.words.insert(t[i].text);
                if (i < scan.camera_end) copy.camera_words.insert(t[i].text);
            }
            // Inside a macro's arguments a texture is an argument: it stays.
            if (is(t, i, "(")) ++scan.parentheses;
            if (is(t, i, ")")) scan.parentheses = std::max(0, scan.parentheses - 1);
            if (t[i].kind == Token::word && t[i].text == "array")
                scan.array_brace = array_brace_after(t, i);
            if (is(t, i, "{")) {
                const bool nested = !scan.frames.empty() && scan.frames.back().array &&
                                    (is(t, i - 1, "{") || is(t, i - 1, ","));
                scan.frames.push_back({false, i == scan.array_brace || nested});
            } else if (is(t, i, "}")) {
                if (!scan.frames.empty()) {
                    if (scan.frames.back().coloured)
                        scan.edits.push_back(
                            {t[i].begin, t[i].begin, colour_texture(++copy.statements)});
                    scan.frames.pop_back();
                }
            } else if (t[i].kind == Token::directive) {
                i = directive(t, i, relative, scan);
            } else if (t[i].kind == Token::word) {
                i = statement(t, i, scan);
            }
        }
        std::string out = apply_edits(text, std::move(scan.edits));
        if (main_file) out += "\nglobal_settings { assumed_gamma 1 }\nbackground { rgb 0 }\n";
        write(relative, out);
        // The includes it names, rewritten after it (their statements numbered after its own).
        std::vector<fs::path> pending;
        pending.swap(includes_);
        for (const fs::path& include : pending) rewrite(include, false);
    }

    FlatColourCopy copy;

private:
    // Open braces: whether closing one ends a coloured statement, whether it holds an array's
    // elements (values, like a declaration's).
    struct Frame {
        bool coloured = false, array = false;
    };
    // What the scan of a file knows at a token.
    struct Scan {
        std::vector<Edit> edits;
        std::vector<Frame> frames;
        size_t array_brace = std::string::npos;  // the brace after `array [...]...`
        int parentheses = 0;
        size_t camera_end = 0;  // the closing brace of the camera last met: inside it below
    };

    // At directive t[i]: drops `#default { ... }`, notes the files `#include` names. Returns
    // the last token it used.
    size_t directive(const std::vector<Token>& t, size_t i, const fs::path& relative, Scan& scan) {
        if (t[i].text == "default" && is(t, i + 1, "{")) {
            const size_t end = closing(t, i + 1);
            scan.edits.push_back({t[i].begin, t[end].end, ""});
            return end;
        }
        if (t[i].text == "include" && i + 1 < t.size() && t[i + 1].kind == Token::string) {
            const fs::path name = relative.parent_path() / t[i + 1].text;
            if (fs::is_regular_file(source_ / name)) includes_.push_back(name);
        }
        return i;
    }

    // At word t[i]: keeps, removes or colours the statement it may begin. Returns the last
    // token it used.
    size_t statement(const std::vector<Token>& t, size_t i, Scan& scan) {
        const std::string& w = t[i].text;
        const bool declared =
            (i > 0 && is(t, i - 1, "=")) || (!scan.frames.empty() && scan.frames.back().array);
        size_t open = i + 1;
        if (w == "function" && is(t, open, "(")) {  // function(x, y, z) { ... }
            while (open < t.size() && !is(t, open, ")")) ++open;
            ++open;
        }
        if (w == "uv_mapping" && !declared) {  // how textures are laid on: none are left
            scan.edits.push_back({t[i].begin, t[i].end, ""});
            return i;
        }
        if (!is(t, open, "{")) return i;
        if (w == "camera") {
            scan.camera_end = closing(t, open);
            return i;
        }
        if (kKept.count(w) || (declared && !kObjects.count(w)) ||
            (scan.parentheses > 0 && kRemoved.count(w))) {
            // Copied as it is (its words are not the scene's shapes), with the layers that
            // follow a declared layered texture.
            i = closing(t, open);
            while (declared && w == "texture" && i + 2 < t.size() && t[i + 1].kind == Token::word &&
                   t[i + 1].text == w && is(t, i + 2, "{"))
                i = closing(t, i + 2);
            return i;
        }
        if (kRemoved.count(w)) {
            const size_t end = closing(t, open);
            scan.edits.push_back({t[i].begin, t[end].end, ""});
            return end;
        }
        if (kObjects.count(w)) {
            scan.frames.push_back({scan.frames.empty() && !declared, false});
            return open;
        }
        return i;
    }

    void write(const fs::path& relative, const std::string& out) const {
        const fs::path target = target_ / relative;
        fs::create_directories(target.parent_path());
        std::ofstream file(target, std::ios::binary);
        if (!file.write(out.data(), std::streamsize(out.size())))
            throw std::runtime_error("cannot write " + target.string());
    }

    fs::path source_, target_;
    std::set<std::string> done_;
    std::vector<fs::path> includes_;
};

}  // namespace

Rgb flat_colour(int index) {
    if (index < 0 || index > kMaxFlatColour)
        throw std::runtime_error("more than " + std::to_string(kMaxFlatColour) +
                                 " object statements");
    return {(index % 256) / 255.0, (index / 256 % 256) / 255.0, (index / 65536) / 255.0};
}

int flat_colour_index(Rgb c) {
    const auto digit = [](double v) { return int(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
    return digit(c.red) + 256 * digit(c.green) + 65536 * digit(c.blue);
}

FlatColourCopy write_flat_colour_copy(const std::string& scene, const std::string& folder) {
    const fs::path path(scene);
    Rewriter rewriter(path.parent_path(), folder);
    rewriter.rewrite(path.filename(), true);
    rewriter.copy.scene = (fs::path(folder) / path.filename()).string();
    return rewriter.copy;
}

bool geometry_agreement(const std::string& scene, int width, int height, GeometryAgreement& out,
                        std::string& message, const SampleFrame& frame) {
    ScratchDir dir;
    const FlatColourCopy copy = write_flat_colour_copy(scene, dir.path().string());
    const std::string original_folder = fs::path(scene).parent_path().string();
    std::string frame_options;
    tracer::ParseOptions options;
    if (frame.frames > 1) {
        // Frames 1 .. frames, the clock from 0 to 1, as the scene's .ini sets them.
        frame_options = " +KFI1 +KFF" + std::to_string(frame.frames) + " +KI0 +KF1 +SF" +
                        std::to_string(frame.number) + " +EF" + std::to_string(frame.number);
        tracer::AnimationSettings& a = options.animation;
        a.clock_on = true;
        a.initial_frame = 1, a.final_frame = frame.frames;
        a.initial_clock = 0, a.final_clock = 1;
        a.frame_number = frame.number;
        a.clock_delta = 1.0 / (frame.frames - 1);
        a.clock = (frame.number - 1) * a.clock_delta;
    }
    std::vector<uint8_t> pov;
    if (!povray_render(copy.scene, width, height, pov, message, 1, original_folder, frame_options))
        return false;

    options.include_paths = {original_folder};
    options.animation.image_width = width, options.animation.image_height = height;
    const tracer::RenderScene ours(tracer::parse_scene_file(copy.scene, options));
    const double per_square_metre = ours.units().per_square_metre();
    out = {};
    out.statements = copy.statements, out.words = copy.words, out.camera_words = copy.camera_words;
    std::optional<tracer::Material> scratch;
    const std::vector<tracer::SurfaceHit> hits = tracer::centre_hits(ours, width, height);
    for (size_t i = 0; i < hits.size(); ++i) {
        int seen = 0;
        if (hits[i].object >= 0)
            seen = flat_colour_index(per_square_metre * ours.material(hits[i], scratch).emission);
        const uint8_t* p = &pov[3 * i];
        const int pov_seen = flat_colour_index({p[0] / 255.0, p[1] / 255.0, p[2] / 255.0});
        ++out.pixels;
        out.agreeing += seen == pov_seen;
        out.seeing += pov_seen != 0;
    }
    return true;
}

}  // namespace rayset::test
