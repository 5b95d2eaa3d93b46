// Objects: which keyword starts which object, object { } copies, CSG (union, merge,
// intersection, difference), the object modifiers every object takes, and the flattening of
// object trees into world-space instances and lights.
#include <type_traits>
#include <utility>

#include <fmt/format.h>

#include "tracer/scene_language/object_grammar.h"
#include "tracer/scene_language/shape_geometry.h"

namespace rayset::tracer {
namespace {

ObjectRef parse_csg(Parser& p, const Token& keyword);
ObjectRef parse_object_statement(Parser& p, const Token& keyword);

struct ObjectGrammar {
    Keyword keyword;
    ObjectRef (*parse)(Parser&, const Token&);
};

// Every keyword that starts an object (reference manual 3.4.5), and our mesh_file.
const ObjectGrammar kObjectGrammar[] = {
    {Keyword::sphere, parse_sphere},
    {Keyword::box, parse_box},
    {Keyword::cylinder, parse_cylinder},
    {Keyword::cone, parse_cone},
    {Keyword::torus, parse_torus},
    {Keyword::ovus, parse_ovus},
    {Keyword::superellipsoid, parse_superellipsoid},
    {Keyword::plane, parse_plane},
    {Keyword::disc, parse_disc},
    {Keyword::triangle, parse_triangle},
    {Keyword::smooth_triangle, parse_smooth_triangle},
    {Keyword::poly, parse_poly},
    {Keyword::cubic, parse_poly},
    {Keyword::quartic, parse_poly},
    {Keyword::polynomial, parse_polynomial},
    {Keyword::quadric, parse_quadric},
    {Keyword::lathe, parse_lathe},
    {Keyword::prism, parse_prism},
    {Keyword::sor, parse_sor},
    {Keyword::sphere_sweep, parse_sphere_sweep},
    {Keyword::polygon, parse_polygon},
    {Keyword::bicubic_patch, parse_bicubic_patch},
    {Keyword::text, parse_text},
    {Keyword::blob, parse_blob},
    {Keyword::height_field, parse_height_field},
    {Keyword::isosurface, parse_isosurface},
    {Keyword::parametric, parse_parametric},
    {Keyword::julia_fractal, parse_julia_fractal},
    {Keyword::mesh, parse_mesh},
    {Keyword::mesh2, parse_mesh2},
    {Keyword::union_, parse_csg},
    {Keyword::composite, parse_csg},  // POV-Ray's old name for union
    {Keyword::merge, parse_csg},
    {Keyword::intersection, parse_csg},
    {Keyword::difference, parse_csg},
    {Keyword::object, parse_object_statement},
    {Keyword::light_source, parse_light_source},
    {Keyword::light_group, parse_light_group},
};

const ObjectGrammar* grammar_of(const Token& token) {
    Keyword keyword;
    if (!keyword_of(token, keyword)) return nullptr;
    for (const ObjectGrammar& grammar : kObjectGrammar)
        if (grammar.keyword == keyword) return &grammar;
    return nullptr;
}

CsgShape::Operation csg_operation(const Token& keyword) {
    if (keyword.is(Keyword::merge)) return CsgShape::Operation::merge;
    if (keyword.is(Keyword::intersection)) return CsgShape::Operation::intersection;
    if (keyword.is(Keyword::difference)) return CsgShape::Operation::difference;
    return CsgShape::Operation::union_of;
}

// CSG: its objects first, then its modifiers (POV-Ray takes no object after a modifier).
ObjectRef parse_csg(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    auto node = new_node(p, keyword, ObjectNode::Kind::csg);
    CsgShape csg;
    csg.operation = csg_operation(keyword);
    while (starts_object(p, p.peek())) node->children.push_back(parse_object(p));
    if (node->children.size() < 2)
        p.warn(keyword, fmt::format("'{}' with fewer than 2 objects", p.word(keyword)));
    node->shape = csg;
    compute_csg_bounds(*node);
    parse_object_modifiers(p, *node, keyword, open);
    return node;
}

ObjectRef parse_object_statement(Parser& p, const Token& keyword) {
    const Token open = p.expect_open(keyword);
    ObjectRef base;
    if (p.take_declared(base)) {
    } else if (starts_object(p, p.peek())) {
        base = parse_object(p);
    } else {
        p.fail_identifier(p.peek(), "an object identifier or an object after 'object {'");
    }
    // A light takes the object modifiers here too (POV-Ray accepts them; they mean nothing to it).
    auto node = std::make_shared<ObjectNode>(*base);
    parse_object_modifiers(p, *node, keyword, open);
    return node;
}

// ---------------------------------------------------------------- modifiers

// The shapes with a sturm flag (blob, lathe, ovus, poly and its kin, prism, sor, torus).
template <typename T, typename = void>
struct HasSturm : std::false_type {};
template <typename T>
struct HasSturm<T, std::void_t<decltype(std::declval<T&>().sturm)>> : std::true_type {};

bool takes_sturm(const Shape& shape) {
    return std::visit([](const auto& s) { return HasSturm<std::decay_t<decltype(s)>>::value; },
                      shape);
}

void set_sturm(Shape& shape, bool sturm) {
    std::visit(
        [&](auto& s) {
            if constexpr (HasSturm<std::decay_t<decltype(s)>>::value) s.sturm = sturm;
        },
        shape);
}

bool* hierarchy_flag(Shape& shape) {
    if (auto* blob = std::get_if<BlobShape>(&shape)) return &blob->hierarchy;
    if (auto* mesh = std::get_if<MeshShape>(&shape)) return &mesh->hierarchy;
    if (auto* field = std::get_if<HeightFieldShape>(&shape)) return &field->hierarchy;
    return nullptr;
}

void parse_photons(Parser& p, const Token& keyword, ObjectNode& node) {
    const Token open = p.expect_open(keyword);
    ObjectPhotons& photons = node.photons;
    node.photons_given = true;
    for (;;) {
        const Token token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        p.next();
        if (token.is(Keyword::target)) {
            photons.target = true;
            if (p.starts_expression(p.peek()))
                photons.spacing_multiplier = p.parse_float("after 'target'");
        } else if (token.is(Keyword::refraction)) {
            photons.refraction = p.parse_optional_bool();
        } else if (token.is(Keyword::reflection)) {
            photons.reflection = p.parse_optional_bool();
        } else if (token.is(Keyword::collect)) {
            photons.collect = p.parse_optional_bool();
        } else if (token.is(Keyword::pass_through)) {
            photons.pass_through = p.parse_optional_bool();
        } else {
            p.fail_identifier(
                token,
                fmt::format("target, refraction, reflection, collect, pass_through or '}}' to "
                            "close 'photons' opened at {}",
                            p.location_of(open).str()));
        }
    }
    p.expect_close(keyword, open);
}

void parse_object_radiosity(Parser& p, const Token& keyword, ObjectNode& node) {
    const Token open = p.expect_open(keyword);
    while (!p.peek_is(Symbol::rbrace)) {
        const Token token = p.next();
        if (!token.is(Keyword::importance))
            p.fail_identifier(token,
                              fmt::format("importance or '}}' to close 'radiosity' opened at {}",
                                          p.location_of(open).str()));
        const Token at = p.peek();
        const double importance = p.parse_float("after 'importance'");
        if (!(importance > 0 && importance <= 1))
            p.fail(at,
                   fmt::format("radiosity importance must lie in (0, 1], found {}", importance));
        node.radiosity_importance = importance;
    }
    p.expect_close(keyword, open);
}

// Why an object may not be a clipped_by or bounded_by object (POV-Ray takes untextured solid
// objects only), or empty.
std::string unfit_to_clip(const ObjectNode& node) {
    if (node.appearance.texture) return "it has a texture";
    switch (node.kind) {
        case ObjectNode::Kind::light: return "a light_source is not an object with an inside";
        case ObjectNode::Kind::csg:
        case ObjectNode::Kind::light_group:
            for (const ObjectRef& child : node.children) {
                const std::string why = unfit_to_clip(*child);
                if (!why.empty()) return why;
            }
            return "";
        case ObjectNode::Kind::shape: break;
    }
    const Shape& s = node.shape;
    if (const auto* mesh = std::get_if<MeshShape>(&s); mesh && !mesh->mesh->has_inside_vector)
        return "a mesh without inside_vector has no inside";
    if (std::holds_alternative<TriangleShape>(s) ||
        std::holds_alternative<SmoothTriangleShape>(s) ||
        std::holds_alternative<BicubicPatchShape>(s) ||
        std::holds_alternative<ParametricShape>(s) || std::holds_alternative<MeshFileShape>(s))
        return fmt::format("a {} has no inside", shape_keyword(s));
    return "";
}

// clipped_by { OBJECTS } | clipped_by { bounded_by }, bounded_by likewise.
void parse_attached_objects(Parser& p, const Token& keyword, ObjectNode& node) {
    const Token open = p.expect_open(keyword);
    const bool clip = keyword.is(Keyword::clipped_by);
    std::vector<ObjectRef>& target = clip ? node.clipped_by : node.bounded_by;
    const Keyword other = clip ? Keyword::bounded_by : Keyword::clipped_by;
    if (p.peek_is(other)) {
        const Token other_token = p.next();
        const std::vector<ObjectRef>& source = clip ? node.bounded_by : node.clipped_by;
        if (source.empty())
            p.fail(other_token, fmt::format("'{0} {{ {1} }}' without a {1} before it",
                                            p.word(keyword), p.word(other_token)));
        target = source;
    } else {
        if (!starts_object(p, p.peek()))
            p.fail_expected(fmt::format("an object in '{}'", p.word(keyword)), p.peek());
        while (starts_object(p, p.peek())) {
            const Token at = p.peek();
            ObjectRef object = parse_object(p);
            const std::string why = unfit_to_clip(*object);
            if (!why.empty())
                p.fail(at, fmt::format("'{}' takes untextured solid objects: {}", p.word(keyword),
                                       why));
            target.push_back(std::move(object));
        }
    }
    p.expect_close(keyword, open);
}

struct FlagModifier {
    Keyword keyword;
    bool ObjectNode::*flag;
    bool takes_bool;  // `KEYWORD [BOOL]`; else the bare keyword
};

const FlagModifier kFlagModifiers[] = {
    {Keyword::no_image, &ObjectNode::no_image, true},
    {Keyword::no_reflection, &ObjectNode::no_reflection, true},
    {Keyword::no_radiosity, &ObjectNode::no_radiosity, true},
    {Keyword::double_illuminate, &ObjectNode::double_illuminate, true},
    {Keyword::inverse, &ObjectNode::inverse, false},
    {Keyword::uv_mapping, &ObjectNode::uv_mapping, false},
};

bool parse_flag_modifier(Parser& p, ObjectNode& node, Keyword keyword) {
    for (const FlagModifier& modifier : kFlagModifiers)
        if (modifier.keyword == keyword) {
            p.next();
            node.*modifier.flag = modifier.takes_bool ? p.parse_optional_bool() : true;
            return true;
        }
    return false;
}

// sturm, hierarchy, split_union, cutaway_textures: only some objects take them.
bool parse_restricted_modifier(Parser& p, ObjectNode& node, Keyword keyword) {
    const Token token = p.peek();
    auto refuse = [&](const char* which) {
        p.fail(token, fmt::format("'{}' cannot be used with {} (only with {})", p.word(token),
                                  node.kind == ObjectNode::Kind::shape ? shape_keyword(node.shape)
                                                                       : "this object",
                                  which));
    };
    const CsgShape* csg =
        node.kind == ObjectNode::Kind::csg ? std::get_if<CsgShape>(&node.shape) : nullptr;
    if (keyword == Keyword::sturm) {
        if (node.kind != ObjectNode::Kind::shape || !takes_sturm(node.shape))
            refuse("blob, cubic, lathe, ovus, poly, polynomial, prism, quartic, sor and torus");
        p.next();
        set_sturm(node.shape, p.parse_optional_bool());
    } else if (keyword == Keyword::hierarchy) {
        bool* flag = node.kind == ObjectNode::Kind::shape ? hierarchy_flag(node.shape) : nullptr;
        if (!flag) refuse("blob, height_field, mesh and mesh2");
        p.next();
        *flag = p.parse_optional_bool();
    } else if (keyword == Keyword::split_union) {
        if (!csg || csg->operation != CsgShape::Operation::union_of) refuse("union");
        p.next();
        std::get<CsgShape>(node.shape).split_union = p.parse_optional_bool();
    } else if (keyword == Keyword::cutaway_textures) {
        if (!csg || (csg->operation != CsgShape::Operation::intersection &&
                     csg->operation != CsgShape::Operation::difference))
            refuse("intersection and difference");
        p.next();
        node.cutaway_textures = true;
    } else {
        return false;
    }
    return true;
}

}  // namespace

bool keyword_of(const Token& token, Keyword& keyword) {
    if (token.kind != TokenKind::word || !is_keyword(token.name)) return false;
    keyword = static_cast<Keyword>(token.name);
    return true;
}

NodePtr new_node(Parser& p, const Token& keyword, ObjectNode::Kind kind) {
    auto node = std::make_shared<ObjectNode>();
    node->kind = kind;
    node->location = p.location_of(keyword);
    return node;
}

void finish_shape(Parser& p, ObjectNode& node, const Token& keyword, const Token& open) {
    prepare_shape(node.shape);
    compute_shape_bounds(node);
    parse_object_modifiers(p, node, keyword, open);
}

bool parse_node_transform(Parser& p, ObjectNode& node) {
    const Token keyword = p.peek();
    Matrix4 step;
    if (!p.parse_transform_item(step)) return false;
    // POV-Ray keeps a sphere a sphere through these (see ParseBounds).
    const bool uniform = step(0, 1) == 0 && step(0, 2) == 0 && step(1, 0) == 0 && step(1, 2) == 0 &&
                         step(2, 0) == 0 && step(2, 1) == 0 && step(0, 0) == step(1, 1) &&
                         step(1, 1) == step(2, 2);
    const bool similarity = keyword.is(Keyword::translate) || keyword.is(Keyword::rotate) ||
                            (keyword.is(Keyword::scale) && uniform);
    transform_node(node, step, similarity);
    return true;
}

void transform_node(ObjectNode& node, const Matrix4& step, bool similarity) {
    node.transform = step * node.transform;
    transform_appearance(node.appearance, step);  // textures written so far move with the object
    auto carry = [&](ObjectRef& attached) {
        auto moved = std::make_shared<ObjectNode>(*attached);
        transform_node(*moved, step, similarity);
        attached = moved;
    };
    for (ObjectRef& object : node.clipped_by) carry(object);
    for (ObjectRef& object : node.bounded_by) carry(object);
    if (node.looks_like) carry(node.looks_like);
    if (node.projected_through) carry(node.projected_through);
    transform_bounds(node, step, similarity);
}

bool parse_object_modifier(Parser& p, ObjectNode& node) {
    if (parse_node_transform(p, node)) return true;
    if (parse_appearance_modifier(p, node.appearance)) return true;
    const Token token = p.peek();
    Keyword keyword;
    if (!keyword_of(token, keyword)) return false;
    if (parse_flag_modifier(p, node, keyword) || parse_restricted_modifier(p, node, keyword))
        return true;
    switch (keyword) {
        case Keyword::no_shadow:
            p.next();
            node.no_shadow = true;
            node.photons.pass_through =
                true;  // POV-Ray's rule; photons { pass_through off } undoes it
            node.photons_given = true;
            return true;
        case Keyword::hollow:
            p.next();
            node.hollow = p.parse_optional_bool();
            return true;
        case Keyword::photons:
            p.next();
            parse_photons(p, token, node);
            return true;
        case Keyword::radiosity:
            p.next();
            parse_object_radiosity(p, token, node);
            return true;
        case Keyword::clipped_by:
        case Keyword::bounded_by:
            p.next();
            parse_attached_objects(p, token, node);
            return true;
        default: return false;
    }
}

void parse_object_modifiers(Parser& p, ObjectNode& node, const Token& keyword, const Token& open) {
    for (;;) {
        const Token& token = p.peek();
        if (token.is(Symbol::rbrace)) break;
        if (parse_object_modifier(p, node)) continue;
        const bool csg = node.kind == ObjectNode::Kind::csg;
        if (csg && starts_object(p, token))
            p.fail(
                token,
                fmt::format(
                    "an object after the modifiers of '{}' opened at {} (its objects come first)",
                    p.word(keyword), p.location_of(open).str()));
        // What the appearance grammar does not read yet.
        if (token.is(Keyword::normal)) p.fail_not_supported(token, "normal (bump) patterns");
        p.fail_identifier(
            token,
            fmt::format("{}an object modifier or '}}' to close '{}' opened at {}",
                        csg ? "an object, " : "", p.word(keyword), p.location_of(open).str()));
    }
    p.expect_close(keyword, open);
    apply_bounding_rules(node);
}

int parse_count(Parser& p, const std::string& what) {
    const Token at = p.peek();
    const int count = p.parse_int(fmt::format("as the number of {}", what), 0);
    if (count > p.options().max_array_elements)
        p.fail(at,
               fmt::format("{} {}: more than the limit of {} (ParseOptions::max_array_elements)",
                           count, what, p.options().max_array_elements));
    return count;
}

Vec2 parse_vec2(Parser& p, const std::string& what) {
    const Token at = p.peek();
    const Numeric n = p.parse_numeric();
    if (n.terms != 1 && n.terms != 2)
        p.fail(at, fmt::format("expected a 2-D vector {}, found {} terms", what, n.terms));
    const Numeric uv = n.promoted(2);
    return {uv.v[0], uv.v[1]};
}

// ---------------------------------------------------------------- entry points

// Our mesh_file is a statement where no identifier of that name is declared.
bool is_mesh_file(Parser& parser, const Token& token) {
    return token.is(ContextWord::mesh_file) && !parser.lookup_value(token);
}

bool starts_object(Parser& parser, const Token& token) {
    return grammar_of(token) != nullptr || is_mesh_file(parser, token);
}

ObjectRef parse_object(Parser& p) {
    const bool mesh_file = is_mesh_file(p, p.peek());
    const Token keyword = p.next();
    if (mesh_file) return parse_mesh_file(p, keyword);
    const ObjectGrammar* grammar = grammar_of(keyword);
    if (!grammar) p.fail_identifier(keyword, "an object");
    return grammar->parse(p, keyword);
}

// ---------------------------------------------------------------- flattening

namespace {

// What an object takes from the objects it is inside of.
struct Inherited {
    Matrix4 to_world;
    ObjectAppearance appearance;
    bool no_shadow = false, no_image = false, no_reflection = false, no_radiosity = false;
    bool double_illuminate = false, uv_mapping = false, hollow = false;
    double radiosity_importance = 1;
    ObjectPhotons photons;
    bool photons_given = false;
    std::shared_ptr<const LightGroup> light_group;
};

class Flattener {
public:
    explicit Flattener(SceneDescription& scene) : scene_(scene) {}

    // Adds `node`'s instances and lights to the scene.
    void add(const ObjectNode& node, const Inherited& parent) {
        const Inherited here = inherit(node, parent);
        switch (node.kind) {
            case ObjectNode::Kind::light: add_light(node, parent, here); return;
            case ObjectNode::Kind::light_group:
                for (const ObjectRef& child : node.children) add(*child, here);
                return;
            case ObjectNode::Kind::csg:
                if (splits(node)) {
                    for (const ObjectRef& child : node.children) add(*child, here);
                    return;
                }
                break;
            case ObjectNode::Kind::shape: break;
        }
        scene_.objects.push_back(instance(node, parent, here));
    }

private:
    // A union is split into its children unless it is clipped, bounded or inverted, as POV-Ray
    // splits it; a light_group is split likewise (inherit gives its children its group).
    static bool splits(const ObjectNode& node) {
        return std::get<CsgShape>(node.shape).operation == CsgShape::Operation::union_of &&
               !node.inverse && node.clipped_by.empty() && node.bounded_by.empty();
    }

    Inherited inherit(const ObjectNode& node, const Inherited& parent) const {
        Inherited here = parent;
        here.to_world = parent.to_world * node.transform;
        here.appearance = node.appearance;  // in the parent's coordinates: to the world's
        transform_appearance(here.appearance, parent.to_world);
        inherit_appearance(here.appearance, parent.appearance);
        here.no_shadow = parent.no_shadow || node.no_shadow;
        here.no_image = parent.no_image || node.no_image;
        here.no_reflection = parent.no_reflection || node.no_reflection;
        here.no_radiosity = parent.no_radiosity || node.no_radiosity;
        here.double_illuminate = parent.double_illuminate || node.double_illuminate;
        here.uv_mapping = parent.uv_mapping || node.uv_mapping;
        here.hollow = node.hollow.value_or(parent.hollow);
        here.radiosity_importance = node.radiosity_importance.value_or(parent.radiosity_importance);
        if (node.photons_given) here.photons = node.photons, here.photons_given = true;
        if (node.kind == ObjectNode::Kind::light_group) {
            auto group = std::make_shared<LightGroup>();
            group->parent = parent.light_group;
            group->global_lights = node.global_lights;
            group->location = node.location;
            here.light_group = group;
        }
        return here;
    }

    // The instance of a shape or of a CSG kept whole; `here` is what it inherited, combined
    // with its own modifiers.
    ObjectInstance instance(const ObjectNode& node, const Inherited& parent,
                            const Inherited& here) {
        ObjectInstance result;
        result.shape = node.shape;
        result.object_to_world = here.to_world;
        result.appearance = here.appearance;
        result.no_shadow = here.no_shadow;
        result.no_image = here.no_image;
        result.no_reflection = here.no_reflection;
        result.no_radiosity = here.no_radiosity;
        result.double_illuminate = here.double_illuminate;
        result.hollow = here.hollow;
        result.inverse = node.inverse;
        result.uv_mapping = here.uv_mapping;
        result.cutaway_textures = node.cutaway_textures;
        result.photons = here.photons;
        result.radiosity_importance = here.radiosity_importance;
        result.light_group = here.light_group;
        result.location = node.location;
        for (const ObjectRef& clip : node.clipped_by)
            result.clipped_by.push_back(bare_instance(*clip, parent));
        for (const ObjectRef& bound : node.bounded_by)
            result.bounded_by.push_back(bare_instance(*bound, parent));
        if (auto* csg = std::get_if<CsgShape>(&result.shape))
            for (const ObjectRef& child : node.children) add_child(*csg, *child, here);
        return result;
    }

    // A child of a CSG kept whole: lights are the scene's, light groups are unions of their
    // children with the group inherited.
    void add_child(CsgShape& csg, const ObjectNode& child, const Inherited& parent) {
        const Inherited here = inherit(child, parent);
        if (child.kind == ObjectNode::Kind::light) return add_light(child, parent, here);
        if (child.kind == ObjectNode::Kind::light_group) {
            ObjectInstance group;
            CsgShape members;
            for (const ObjectRef& member : child.children) add_child(members, *member, here);
            group.shape = members;
            group.object_to_world = here.to_world;
            group.light_group = here.light_group;
            group.location = child.location;
            csg.children.push_back(std::move(group));
            return;
        }
        csg.children.push_back(instance(child, parent, here));
    }

    // clipped_by, bounded_by and projected_through objects: shapes only, no appearance.
    ObjectInstance bare_instance(const ObjectNode& node, const Inherited& parent) {
        Inherited bare;
        bare.to_world = parent.to_world;
        const Inherited here = inherit(node, bare);
        return instance(node, bare, here);
    }

    void add_light(const ObjectNode& node, const Inherited& parent, const Inherited& here) {
        LightSource light = node.light;
        const Matrix4& m = here.to_world;
        light.position = m.point(light.position);
        light.point_at = m.point(light.point_at);
        light.axis1 = m.vector(light.axis1);
        light.axis2 = m.vector(light.axis2);
        light.light_group = here.light_group;
        if (node.projected_through)
            light.projected_through.push_back(bare_instance(*node.projected_through, parent));
        const int index = static_cast<int>(scene_.lights.size());
        scene_.lights.push_back(std::move(light));
        if (node.looks_like) {
            // POV-Ray gives it no_shadow so that it does not block its own light.
            Inherited shown = parent;
            shown.no_shadow = true;
            shown.light_group = here.light_group;
            const size_t first = scene_.objects.size();
            add(*node.looks_like, shown);
            for (size_t k = first; k < scene_.objects.size(); ++k)
                scene_.objects[k].looks_like_of = index;
        }
    }

    SceneDescription& scene_;
};

}  // namespace

void add_to_scene(Parser& parser, const ObjectRef& object, const Token& at) {
    Inherited root;
    root.appearance = scene_default_appearance(parser);  // the #default texture of this moment
    const SceneDescription& scene = parser.scene();
    Flattener(parser.scene()).add(*object, root);
    const ParseOptions& options = parser.options();
    if (long(scene.objects.size()) > options.max_objects)
        parser.fail(at, fmt::format("object limit: more than {} objects in the scene "
                                    "(ParseOptions::max_objects, raytrace --max-objects)",
                                    options.max_objects));
    if (long(scene.lights.size()) > options.max_lights)
        parser.fail(at, fmt::format("light limit: more than {} light sources in the scene "
                                    "(ParseOptions::max_lights, raytrace --max-lights)",
                                    options.max_lights));
}

}  // namespace rayset::tracer
