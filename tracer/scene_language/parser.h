// The interpreter of POV-Ray's scene language. Parser is the language machine: tokens across
// files, macros and loops; directives; identifiers and their scopes; expressions, colours,
// strings, arrays, functions and splines. The grammar of scene items (objects, textures,
// cameras, ...) lives in the grammar_*.cpp files as free functions over Parser's public API.
//
// Directives are executed and macros expanded as tokens are fetched, as POV-Ray does, so they
// may appear anywhere. Files:
//   token_stream.cpp  frames (files, macro bodies), lookahead, identifier resolution, errors
//   directives.cpp    #declare #local #undef #if #ifdef #ifndef #elseif #else #switch #case
//                     #range #break #while #for #end #include #version #debug #warning #error
//   macros.cpp        #macro definitions and invocations
//   file_io.cpp       #fopen #fclose #read #write
//   symbols.cpp       scopes: #declare / #local rules, parameters passed by reference
//   expression.cpp    numeric expressions, colours
//   builtins.cpp      built-in float, vector and string functions and variables
//   rvalue.cpp        what may follow '=': every kind of value, arrays and their initialisers
//   functions.cpp     user-defined functions (function { ... }) compiled and evaluated
//   splines.cpp       spline { ... } and its evaluation
//   scene_language.cpp  the top level and the entry points
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "tracer/scene_language/lexer.h"
#include "tracer/scene_language/scene_language.h"
#include "tracer/scene_language/symbol_table.h"
#include "tracer/scene_language/values.h"

namespace rayset::tracer {

// What a value or token is read for, in messages ("as the sphere radius"): text, or a callable
// that makes it, so that a message is only formatted when there is an error to report.
class Purpose {
public:
    Purpose(const char* text = "") : text_(text) {}
    Purpose(const std::string& text) : text_(text.c_str()) {}
    template <typename Make,
              typename = std::enable_if_t<std::is_invocable_r_v<std::string, const Make&>>>
    Purpose(const Make& make)
        : object_(&make),
          make_([](const void* object) { return (*static_cast<const Make*>(object))(); }) {}
    std::string str() const { return make_ ? make_(object_) : std::string(text_); }

private:
    const char* text_ = "";
    const void* object_ = nullptr;
    std::string (*make_)(const void*) = nullptr;
};

class Parser {
public:
    explicit Parser(const ParseOptions& options);
    ~Parser();
    SceneDescription parse(const std::string& text, const std::string& path);

    // ---------------------------------------------------------------- tokens
    // The next token, after running the directives and expanding the macros before it.
    const Token& peek();
    Token next();
    bool peek_is(Symbol symbol) { return peek().is(symbol); }
    bool peek_is(Keyword keyword) { return peek().is(keyword); }
    bool accept(Symbol symbol);
    bool accept(Keyword keyword);
    void accept_comma() { accept(Symbol::comma); }
    Token expect(Symbol symbol, Purpose purpose);
    Token expect(Keyword keyword, Purpose purpose);
    // '{' after `keyword`, counted against the nesting limit until its expect_close.
    Token expect_open(const Token& keyword);
    void expect_close(const Token& keyword, const Token& open);
    // The parentheses and commas of a call name(a, b): the errors name the function, and the
    // closing one where its '(' opened.
    Token open_call(const Token& name);
    void call_comma(const Token& name);
    void close_call(const Token& name, const Token& open);
    // The value of the declared identifier that is the lookahead token, or nullptr. Valid until
    // the next token is taken.
    const Value* peek_value();
    template <typename T>
    const T* peek_declared() {
        const Value* value = peek_value();
        return value ? std::get_if<T>(value) : nullptr;
    }
    // When the next token is an identifier, or an array element `A[i]...`, holding a T: takes it
    // into `out` and returns true; false (nothing taken) otherwise.
    template <typename T>
    bool take_declared(T& out) {
        if (const T* value = peek_declared<T>()) {
            out = *value;
            next();
            return true;
        }
        const ArrayRef* array = peek_declared<ArrayRef>();
        if (!array || (*array)->element_type != Value(T{}).index()) return false;
        const Token at = peek();
        const Value element = parse_rvalue(at);
        if (const T* value = std::get_if<T>(&element)) {
            out = *value;
            return true;
        }
        fail(at, "expected an element of '" + word(at) + "', found " + type_name(element));
    }

    // The value of the identifier `token` names, or nullptr (it is a keyword or undeclared).
    const Value* lookup_value(const Token& token) const {
        const SymbolRef& symbol =
            token.kind == TokenKind::word ? symbols_.find(token.name) : SymbolTable::kNone;
        return symbol ? &symbol->value : nullptr;
    }
    const std::string& word(const Token& token) const { return names_.text(token.name); }
    const std::string& string_literal(const Token& token) const;
    std::string describe(const Token& token) const;  // "'sphere'", "number 3", "end of file" ...
    NameTable& names() { return names_; }

    // ---------------------------------------------------------------- values
    bool starts_expression(const Token& token);
    // The full grammar: c ? a : b, & |, relational operators (also on strings).
    Numeric parse_expression();
    // What POV-Ray's float and vector parameters read: + - * / and unary operators, no
    // comparisons (so `box { <0,0,0> <1,1,1> }` is two corners); parentheses bring the full
    // grammar back.
    Numeric parse_numeric();
    double parse_float(Purpose purpose = {});
    int parse_int(Purpose purpose, int minimum);
    Vec3 parse_vector();                    // three terms: a float promotes, a 2-vector pads
    Numeric parse_vector_terms(int terms);  // exactly `terms` terms, promoted the same way
    // `keyword [BOOL]`: true when no value follows.
    bool parse_optional_bool();
    bool starts_colour(const Token& token);
    Colour parse_colour();  // [color] COLOR_BODY, all five terms
    bool starts_string(const Token& token);
    std::string parse_string();
    // Anything that may follow '=' in #declare, or be passed to a macro.
    Value parse_rvalue(const Token& purpose);
    // translate, rotate, scale, matrix, transform; false (nothing read) for anything else.
    bool parse_transform_item(Matrix4& transform);
    Matrix4 parse_transform_block(const Token& keyword);
    // After `function`: a user-defined function.
    FunctionRef parse_function(const Token& keyword);
    SplineRef parse_spline(const Token& keyword);

    // ---------------------------------------------------------------- errors and files
    SourceLocation location_of(const Token& token) const;
    [[noreturn]] void fail(const Token& at, const std::string& what) const;
    [[noreturn]] void fail_expected(const std::string& expected, const Token& found) const;
    [[noreturn]] void fail_not_supported(const Token& at, const std::string& feature) const;
    // An unknown identifier, a keyword out of place, or a value of the wrong type.
    [[noreturn]] void fail_identifier(const Token& at, const std::string& expected);
    void warn(const Token& at, const std::string& what);
    // Resolves a file name against the folder of the file naming it, then the include paths,
    // refusing what lands outside the allowed roots. `what` names the file in messages.
    // A name without an extension is also tried with each of `extensions` (".png"), as POV-Ray
    // tries its file types'.
    std::string resolve_file(const std::string& name, const Token& at, const std::string& what,
                             std::initializer_list<const char*> extensions = {}) const;

    // ---------------------------------------------------------------- scene state
    SceneDescription& scene() { return scene_; }
    const ParseOptions& options() const { return options_; }
    double language_version() const { return version_; }
    // The texture #default sets (null: POV-Ray's default), for the appearance grammar.
    TextureRef default_texture;

    // Counts one level of nesting (a block, a parenthesis, a call) against max_nesting.
    class Nesting {
    public:
        Nesting(Parser& parser, const Token& at);
        ~Nesting() { --parser_.nesting_; }
        Nesting(const Nesting&) = delete;
        Nesting& operator=(const Nesting&) = delete;

    private:
        Parser& parser_;
    };

private:
    friend class FunctionCompiler;

    // ---------------------------------------------------------------- token stream
    struct FileInfo {
        std::shared_ptr<SourceFile> source;
        bool included = false;
        Token included_at;  // the #include directive
    };
    enum class FrameKind { file, macro };
    struct Frame {
        std::shared_ptr<const SourceFile> source;
        size_t pos = 0;
        FrameKind kind = FrameKind::file;
        size_t blocks_at_start = 0;
    };
    // A conditional, loop, switch or macro body in progress.
    struct Block {
        enum class Kind {
            if_branch,
            else_branch,
            while_loop,
            for_loop,
            switch_clause,
            macro_body
        } kind;
        Token opened;         // the directive (or macro name) that opened it
        size_t frame = 0;     // frames_ index it belongs to
        size_t restart = 0;   // while: index of its #while; for: its first body token
        NameId variable = 0;  // for: the loop variable
        double last = 0, step = 1;
    };
    void push_file(const std::string& text, const std::string& shown_path,
                   const std::string& directory, const Token* included_at);
    void leave_finished_files();  // pops the frames of included files that have ended
    Token raw_next();             // next token of the innermost frame, leaving finished files
    const Token& raw_peek();      // the same without taking it (no directives, no macros)
    NameId next_raw_identifier(const std::string& purpose);
    void fill_lookahead();
    // peek() where an operator may come next: there a directive may end a directive's expression.
    const Token& peek_operator();
    bool directive_ends_expression() const;
    void give_back_lookahead();
    SymbolRef resolve(NameId name) const;

    // ---------------------------------------------------------------- directives
    void run_directive(const Token& directive);
    void directive_declare(const Token& directive, bool local);
    void directive_if(const Token& directive);
    void directive_ifdef(const Token& directive, bool want_defined);
    void directive_else(const Token& directive);
    void directive_switch(const Token& directive);
    void directive_case(const Token& directive);
    void directive_break(const Token& directive);
    void directive_while(const Token& directive);
    void directive_for(const Token& directive);
    void directive_end(const Token& directive);
    void directive_include(const Token& directive);
    void directive_version(const Token& directive);
    void directive_message(const Token& directive);
    void directive_undef(const Token& directive);
    void directive_default(const Token& directive);
    void directive_macro(const Token& directive);
    void directive_fopen(const Token& directive);
    void directive_fclose(const Token& directive);
    void directive_read(const Token& directive);
    void directive_write(const Token& directive);
    double parse_condition(const Token& directive);
    // Takes the branches after a false condition: the next #elseif, #else or #end.
    void take_branch_after(const Token& opened, bool allow_elseif);
    // Skips the current frame's tokens to the first directive of `stops` at nesting depth
    // `depth` (nested blocks skipped whole) and returns it.
    Token skip_to(const Token& opened, std::initializer_list<Keyword> stops, int depth = 0);
    void enter_block(Block::Kind kind, const Token& opened);
    void leave_macro();
    bool is_defined(
        const Token& at);  // the identifier or array element after '(' of #ifdef/defined

    // ---------------------------------------------------------------- macros
    void invoke_macro(const Token& name, const MacroRef& macro);

    // ---------------------------------------------------------------- symbols
    SymbolRef lookup(NameId name) const;
    // #declare (local false) or #local (local true) of a value, as POV-Ray's scope rules say.
    static constexpr size_t kInnermostScope = ~size_t{0};
    void assign(const Token& at, NameId name, Value value, bool local,
                const std::string& deprecation = "", bool warn_once = false,
                size_t scope = kInnermostScope);
    void check_declarable(const Token& at, NameId name, const char* directive);
    // The array element `A[i][j]...` after the identifier A (the brackets are next).
    Value* array_element(const Token& at, Array& array, bool for_assignment);

    // ---------------------------------------------------------------- expressions
    Numeric parse_conditional();  // the full grammar, without the rounding of parse_expression
    Numeric parse_logical();
    Numeric parse_relational();
    Numeric parse_term();
    Numeric parse_term_after(Numeric first);  // * / with `first` already read
    Numeric parse_unary();
    Numeric parse_primary();
    Numeric parse_postfix(Numeric value);
    Numeric parse_additive_after(Numeric first);  // + - with `first` already read as a term
    Numeric parse_vector_literal(const Token& open);
    Numeric parse_numeric_identifier(const Token& token, const Value& value);
    // The built-in constants and functions: their tables and handlers (builtins.cpp).
    class Builtins;
    Numeric parse_builtin_numeric(const Token& name);
    // Constants and built-in variables (pi, x, clock, version ...): nothing for anything else.
    std::optional<Numeric> builtin_constant(const Token& name) const;
    bool is_numeric_builtin(NameId name) const;
    Numeric call_function(const Token& name, const UserFunction& function);
    Numeric call_spline(const Token& name, const Spline& spline);
    std::string parse_builtin_string(const Token& name);
    Colour parse_colour_body(const Token& start, bool keyword_given);
    // parse_rvalue by its first token: a keyword, the layered texture, a declared identifier.
    Value parse_keyword_rvalue(const Token& token);
    Value parse_layered_texture_rvalue();
    Value parse_identifier_rvalue(const Token& token, const Token& purpose);
    Value parse_array(const Token& keyword);
    void parse_array_initialiser(Array& array, size_t dimension, size_t& index,
                                 const Token& keyword);

    // ---------------------------------------------------------------- limits
    // Fails when the process has grown (or would grow by `more_bytes`) past the memory limit.
    void check_memory(const Token& at, double more_bytes = 0);
    void count_iteration(const Token& at);

    const ParseOptions& options_;
    std::vector<std::string> search_paths_;  // options' include paths, then POV-Ray's
    NameTable names_;
    SceneDescription scene_;
    std::vector<FileInfo> files_;
    std::vector<Frame> frames_;
    std::vector<Block> blocks_;
    SymbolTable symbols_;
    std::vector<std::string> allowed_roots_, write_roots_;
    // The one lookahead token and, for a declared identifier, its entry.
    bool have_lookahead_ = false;
    Token lookahead_;
    SymbolRef lookahead_symbol_;
    size_t directive_position_ = 0;  // index of the directive being run in its frame
    // Frame depth of the directive whose expression is being read: a directive met in that
    // frame ends the expression instead of running.
    size_t directive_frame_ = 0;
    bool operator_position_ = false;  // peek_operator() is looking
    int nesting_ = 0;
    long loop_iterations_ = 0;
    long macro_calls_ = 0;
    double version_ = 3.7;
    bool version_seen_ = false;
    size_t tokens_since_memory_check_ = 0;
    long baseline_rss_kb_ = 0;
    struct RandomStream {
        uint32_t state = 0;
    };
    std::vector<RandomStream> random_streams_;
    std::chrono::system_clock::time_point start_time_;
};

// The keywords that start a colour: colour, rgb ... srgbft, red, green, blue, filter, transmit.
bool is_colour_keyword(const Token& token);

}  // namespace rayset::tracer
