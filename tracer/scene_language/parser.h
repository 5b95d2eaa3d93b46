// The parser's shared state and the methods the files of this folder implement:
//   token_stream.cpp  tokens across included files, lookahead, error helpers
//   directives.cpp    #declare #local #undef #if #ifdef #ifndef #elseif #else #while #end
//                     #include #version #error, symbol scopes, file resolution
//   expression.cpp    numeric expressions, colours, strings
//   objects.cpp       shapes, unions, object{}, light_source, transforms, object modifiers
//   materials.cpp     texture, pigment, finish, interior
//   scene_items.cpp   camera, global_settings, background, ray_source, illuminance_receiver
//   scene_language.cpp  the top level and the flattening of object trees into instances
// Directives are executed as tokens are fetched, as POV-Ray does, so they may appear anywhere.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

#include "tracer/scene_language/lexer.h"
#include "tracer/scene_language/scene_language.h"
#include "tracer/scene_language/values.h"

namespace rayset::tracer {

class Parser {
public:
    explicit Parser(const ParseOptions& options) : options_(options) {}
    SceneDescription parse(const std::string& text, const std::string& path);

private:
    // ---- token stream (token_stream.cpp)
    struct FileInfo {
        std::string path;       // as shown in messages
        std::string directory;  // where relative names start
        bool included = false;
        Token included_at;      // the #include directive
    };
    struct Frame {
        int file = 0;
        std::vector<Token> tokens;
        size_t pos = 0;
        size_t conditionals_at_start = 0;
    };
    void push_file(const std::string& text, const std::string& shown_path, const std::string& directory,
                   const Token* included_at);
    Token raw_next();  // next token of the innermost file, popping finished files
    const Token& peek();
    Token next();
    bool peek_symbol(const char* symbol);
    bool accept_symbol(const char* symbol);
    bool peek_word(const char* word);
    bool accept_word(const char* word);
    Token expect_symbol(const char* symbol, const std::string& purpose);
    Token expect_open(const Token& keyword);
    void expect_close(const Token& keyword, const Token& open);
    void accept_comma() { accept_symbol(","); }
    SourceLocation location_of(const Token& token) const;
    [[noreturn]] void fail(const Token& at, const std::string& what) const;
    [[noreturn]] void fail_expected(const std::string& expected, const Token& found) const;
    [[noreturn]] void fail_not_supported(const Token& at, const std::string& feature) const;
    // Unknown identifier, POV-Ray keyword outside the subset, or a value of the wrong type.
    [[noreturn]] void fail_identifier(const Token& at, const std::string& expected) const;

    // ---- directives (directives.cpp)
    void run_directive(const Token& directive);
    void directive_declare(const Token& directive, bool local);
    void directive_if(const Token& directive);
    void directive_ifdef(const Token& directive, bool want_defined);
    void directive_while(const Token& directive);
    void directive_end(const Token& directive);
    void directive_else(const Token& directive);
    void directive_include(const Token& directive);
    // Skips tokens of the current file to the #else/#elseif/#end matching `opened` (nested blocks
    // skipped whole) and returns the directive it stopped at.
    Token skip_block(const Token& opened, bool stop_at_else);
    [[noreturn]] void fail_unclosed(const Token& opened) const;
    Value parse_declared_value(const Token& name);
    const Value* lookup(const std::string& name) const;
    // Resolves a file name against the folder of the file naming it, then the include paths,
    // refusing what lands outside the allowed roots. `what` names the file in messages.
    std::string resolve_file(const std::string& name, const Token& at, const std::string& what) const;

    // ---- expressions (expression.cpp)
    bool starts_expression(const Token& token) const;
    Numeric parse_expression();  // full POV-Ray expression (ternary, logical, relational)
    Numeric parse_additive();    // what POV-Ray's Parse_Float/Parse_Vector read: no comparisons
    Numeric parse_logical();
    Numeric parse_relational();
    Numeric parse_term();
    Numeric parse_unary();
    Numeric parse_primary();
    Numeric parse_function(const Token& name);
    Numeric parse_vector_literal(const Token& open);
    double parse_float();
    double parse_float(const std::string& purpose);
    int parse_int(const std::string& purpose, int minimum);
    Vec3 parse_vector();
    bool parse_optional_bool();  // `hollow`, `hollow on`, `jitter off`
    Colour parse_colour(bool with_filter_transmit);
    std::string parse_string();

    // ---- objects (objects.cpp)
    bool starts_object(const Token& token) const;
    ObjectRef parse_object();
    ObjectRef parse_shape(const Token& keyword);
    ObjectRef parse_union(const Token& keyword);
    ObjectRef parse_object_statement(const Token& keyword);
    ObjectRef parse_mesh(const Token& keyword);
    ObjectRef parse_mesh2(const Token& keyword);
    ObjectRef parse_mesh_file(const Token& keyword);
    ObjectRef parse_light_source(const Token& keyword);
    bool parse_light_modifier(LightSource& light);
    bool parse_transform_item(Matrix4& transform);  // applies after what `transform` holds
    Matrix4 parse_transform_block(const Token& keyword);
    bool parse_object_modifier(ObjectNode& node);
    void parse_object_modifiers(ObjectNode& node, const Token& keyword, const Token& open);

    // ---- materials (materials.cpp)
    Texture parse_texture(const Token& keyword);
    Pigment parse_pigment(const Token& keyword);
    Finish parse_finish(const Token& keyword);
    Interior parse_interior(const Token& keyword);
    void parse_pigment_body(Pigment& pigment, const Token& keyword, const Token& open);
    void parse_finish_body(Finish& finish, const Token& keyword, const Token& open);
    Rgb parse_rgb();

    // ---- scene items (scene_items.cpp)
    Camera parse_camera(const Token& keyword);
    void parse_global_settings(const Token& keyword);
    void parse_radiosity(const Token& keyword);
    void parse_background(const Token& keyword);
    void parse_ray_source(const Token& keyword);
    void parse_receiver(const Token& keyword);

    // ---- flattening (scene_language.cpp)
    struct Inherited {
        Matrix4 to_world;
        const Texture* texture = nullptr;
        const Interior* interior = nullptr;
        bool no_shadow = false, no_image = false, no_reflection = false, hollow = false;
    };
    void flatten(const ObjectNode& node, const Inherited& parent);

    struct Conditional {
        enum class Kind { if_branch, else_branch, while_loop } kind;
        Token opened;       // the directive that opened it
        size_t frame = 0;   // frame index it belongs to
        size_t loop_start = 0;  // token index of the #while directive
    };

    const ParseOptions& options_;
    SceneDescription scene_;
    std::vector<FileInfo> files_;
    std::vector<Frame> frames_;
    std::vector<Conditional> conditionals_;
    std::vector<std::unordered_map<std::string, Value>> scopes_;  // [0] global, one per include
    std::vector<std::string> allowed_roots_;
    std::vector<Token> lookahead_;
    int directive_depth_ = 0;  // >0 while a directive reads its expression: directives then end it
    long loop_iterations_ = 0;
};

}  // namespace rayset::tracer
