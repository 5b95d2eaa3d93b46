// Language directives, executed when the token stream reaches them: declarations and their
// scopes, conditionals and loops (by re-reading the loop's tokens), includes and #version.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "tracer/scene_language/parser.h"
#include "tracer/scene_language/pov_keywords.h"

namespace rayset::tracer {
namespace fs = std::filesystem;

namespace {

bool opens_block(const std::string& directive) {
    return directive == "if" || directive == "ifdef" || directive == "ifndef" || directive == "while" ||
           directive == "switch" || directive == "macro" || directive == "for";
}

bool within(const fs::path& path, const fs::path& root) {
    auto p = path.begin();
    for (auto r = root.begin(); r != root.end(); ++r, ++p) {
        if (r->empty()) continue;  // trailing separator
        if (p == path.end() || *p != *r) return false;
    }
    return true;
}

// RAII: while a directive reads its own tokens, a directive it meets ends its expression.
struct DirectiveScope {
    explicit DirectiveScope(int& depth) : depth_(depth) { ++depth_; }
    ~DirectiveScope() { --depth_; }
    int& depth_;
};

}  // namespace

void Parser::run_directive(const Token& directive) {
    DirectiveScope scope(directive_depth_);
    const std::string& name = directive.text;
    if (name == "declare") return directive_declare(directive, false);
    if (name == "local") return directive_declare(directive, true);
    if (name == "if") return directive_if(directive);
    if (name == "ifdef") return directive_ifdef(directive, true);
    if (name == "ifndef") return directive_ifdef(directive, false);
    if (name == "while") return directive_while(directive);
    if (name == "end") return directive_end(directive);
    if (name == "else" || name == "elseif") return directive_else(directive);
    if (name == "include") return directive_include(directive);
    if (name == "version") {
        scene_.version = parse_float("after #version");
        accept_symbol(";");
        return;
    }
    if (name == "undef") {
        const Token id = next();
        if (id.kind != TokenKind::identifier) fail_expected("an identifier after #undef", id);
        for (auto scope_it = scopes_.rbegin(); scope_it != scopes_.rend(); ++scope_it)
            if (scope_it->erase(id.text)) return;
        return;
    }
    if (name == "error") fail(directive, fmt::format("#error: {}", parse_string()));
    fail_not_supported(directive, fmt::format("#{}", name));
}

const Value* Parser::lookup(const std::string& name) const {
    for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope) {
        auto found = scope->find(name);
        if (found != scope->end()) return &found->second;
    }
    return nullptr;
}

void Parser::directive_declare(const Token& directive, bool local) {
    const Token name = next();
    if (name.kind != TokenKind::identifier) fail_expected(fmt::format("an identifier after #{}", directive.text), name);
    if (is_pov_keyword(name.text))
        fail(name, fmt::format("cannot #{} '{}': it is a reserved word", directive.text, name.text));
    if (peek_symbol("[")) fail_not_supported(peek(), "arrays");
    expect_symbol("=", fmt::format("after #{} {}", directive.text, name.text));
    Value value = parse_declared_value(name);
    accept_symbol(";");
    auto& scope = local ? scopes_.back() : scopes_.front();
    scope[name.text] = std::move(value);
}

Value Parser::parse_declared_value(const Token& name) {
    const Token& first = peek();
    // Objects, textures and the like contain blocks in which directives work as anywhere else.
    const int saved_depth = directive_depth_;
    struct Restore {
        int& depth;
        int saved;
        ~Restore() { depth = saved; }
    } restore{directive_depth_, saved_depth};
    if (first.kind == TokenKind::identifier) {
        const std::string word = first.text;
        if (starts_object(first)) {
            directive_depth_ = 0;
            return parse_object();
        }
        const Token keyword = first;
        if (word == "texture" || word == "pigment" || word == "finish" || word == "interior" ||
            word == "transform" || word == "camera") {
            next();
            directive_depth_ = 0;
            if (word == "texture") return parse_texture(keyword);
            if (word == "pigment") return parse_pigment(keyword);
            if (word == "finish") return parse_finish(keyword);
            if (word == "interior") return parse_interior(keyword);
            if (word == "transform") return TransformValue{parse_transform_block(keyword)};
            return parse_camera(keyword);
        }
        if (word == "concat") return parse_string();
        if (const Value* value = lookup(word)) {
            if (!std::holds_alternative<Numeric>(*value)) {
                next();
                return *value;
            }
        }
    }
    if (first.kind == TokenKind::string) return parse_string();
    if (!starts_expression(first)) fail_identifier(first, fmt::format("a value for '{}'", name.text));
    return parse_expression();
}

void Parser::directive_if(const Token& directive) {
    const size_t frames = frames_.size();
    const bool condition = std::fabs(parse_float(fmt::format("as the #if condition"))) > 1e-10;
    if (frames_.size() != frames) fail_unclosed(directive);
    if (condition) {
        conditionals_.push_back({Conditional::Kind::if_branch, directive, frames_.size() - 1, 0});
        return;
    }
    for (;;) {
        const Token stop = skip_block(directive, true);
        if (stop.text == "end") return;
        if (stop.text == "else") {
            conditionals_.push_back({Conditional::Kind::else_branch, directive, frames_.size() - 1, 0});
            return;
        }
        // #elseif: its condition decides; a false one skips on to the next branch.
        if (std::fabs(parse_float("as the #elseif condition")) > 1e-10) {
            conditionals_.push_back({Conditional::Kind::if_branch, directive, frames_.size() - 1, 0});
            return;
        }
    }
}

void Parser::directive_ifdef(const Token& directive, bool want_defined) {
    expect_symbol("(", fmt::format("after #{}", directive.text));
    const Token id = next();
    if (id.kind != TokenKind::identifier) fail_expected(fmt::format("an identifier in #{}", directive.text), id);
    expect_symbol(")", fmt::format("after the identifier of #{}", directive.text));
    if ((lookup(id.text) != nullptr) == want_defined) {
        conditionals_.push_back({Conditional::Kind::if_branch, directive, frames_.size() - 1, 0});
        return;
    }
    const Token stop = skip_block(directive, true);
    if (stop.text == "else") conditionals_.push_back({Conditional::Kind::else_branch, directive, frames_.size() - 1, 0});
    else if (stop.text == "elseif") fail_not_supported(stop, "#elseif after #ifdef/#ifndef");
}

void Parser::directive_while(const Token& directive) {
    const size_t frame = frames_.size() - 1;
    // raw_next has just handed out the directive: its index is one before the frame's position
    // (the lookahead, if any, was taken after it).
    const size_t start = frames_[frame].pos - 1 - lookahead_.size();
    const bool condition = std::fabs(parse_float("as the #while condition")) > 1e-10;
    if (frames_.size() != frame + 1) fail_unclosed(directive);
    if (!condition) {
        skip_block(directive, false);
        return;
    }
    if (++loop_iterations_ > options_.max_loop_iterations)
        fail(directive, fmt::format("loop limit: more than {} #while iterations in total", options_.max_loop_iterations));
    conditionals_.push_back({Conditional::Kind::while_loop, directive, frame, start});
}

void Parser::directive_end(const Token& directive) {
    if (conditionals_.size() <= frames_.back().conditionals_at_start)
        fail(directive, "#end without an open #if, #ifdef, #ifndef or #while in this file");
    const Conditional top = conditionals_.back();
    conditionals_.pop_back();
    if (top.kind == Conditional::Kind::while_loop) {
        lookahead_.clear();  // nothing read past #end belongs to the loop's next pass
        frames_[top.frame].pos = top.loop_start;
    }
}

void Parser::directive_else(const Token& directive) {
    if (conditionals_.size() <= frames_.back().conditionals_at_start ||
        conditionals_.back().kind != Conditional::Kind::if_branch)
        fail(directive, fmt::format("#{} without a matching #if", directive.text));
    // The taken branch ends here: skip the remaining branches to the #end.
    const Token opened = conditionals_.back().opened;
    conditionals_.pop_back();
    for (;;) {
        const Token stop = skip_block(opened, false);
        if (stop.text == "end") return;
    }
}

void Parser::fail_unclosed(const Token& opened) const {
    // The condition ran into the end of its file (which was then left): report it there.
    fail(opened, fmt::format("unclosed #{}: expected #end before the end of its file", opened.text));
}

Token Parser::skip_block(const Token& opened, bool stop_at_else) {
    if (!lookahead_.empty()) {
        --frames_.back().pos;  // the lookahead is the first token to skip
        lookahead_.clear();
    }
    Frame& frame = frames_.back();
    int depth = 0;
    for (;;) {
        const Token& token = frame.tokens[frame.pos];
        if (token.kind == TokenKind::end)
            fail(token, fmt::format("unclosed #{} opened at {}: expected #end before end of file", opened.text,
                                    location_of(opened).str()));
        ++frame.pos;
        if (token.kind != TokenKind::directive) continue;
        if (opens_block(token.text)) {
            ++depth;
        } else if (token.text == "end") {
            if (depth == 0) return token;
            --depth;
        } else if (depth == 0 && stop_at_else && (token.text == "else" || token.text == "elseif")) {
            return token;
        }
    }
}

void Parser::directive_include(const Token& directive) {
    const std::string name = parse_string();
    if (static_cast<int>(frames_.size()) >= options_.max_include_depth)
        fail(directive, fmt::format("include depth limit: more than {} nested #include levels (recursive include of \"{}\"?)",
                                    options_.max_include_depth, name));
    const std::string path = resolve_file(name, directive, "include file");
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(directive, fmt::format("include file \"{}\" cannot be read ({})", name, path));
    std::ostringstream text;
    text << in.rdbuf();
    push_file(text.str(), path, fs::path(path).parent_path().string(), &directive);
}

std::string Parser::resolve_file(const std::string& name, const Token& at, const std::string& what) const {
    std::vector<fs::path> candidates;
    const fs::path given(name);
    if (given.is_absolute()) {
        candidates.push_back(given);
    } else {
        candidates.push_back(fs::path(files_[at.file].directory) / given);
        for (const std::string& folder : options_.include_paths) candidates.push_back(fs::path(folder) / given);
    }
    for (const fs::path& candidate : candidates) {
        std::error_code error;
        if (!fs::is_regular_file(candidate, error)) continue;
        const fs::path real = fs::weakly_canonical(candidate, error);
        for (const std::string& root : allowed_roots_)
            if (within(real, fs::path(root))) return real.string();
        std::string roots;
        for (const std::string& root : allowed_roots_) roots += (roots.empty() ? "" : ", ") + root;
        fail(at, fmt::format("{} \"{}\" resolves to {}, outside the allowed roots ({})", what, name, real.string(), roots));
    }
    std::string searched;
    for (const fs::path& candidate : candidates) searched += (searched.empty() ? "" : ", ") + candidate.parent_path().string();
    fail(at, fmt::format("{} \"{}\" not found (searched {})", what, name, searched));
}

}  // namespace rayset::tracer
