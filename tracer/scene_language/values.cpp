// Numeric promotion and type names of identifier values.
#include "tracer/scene_language/values.h"

namespace rayset::tracer {

Numeric Numeric::promoted(int to_terms) const {
    if (terms >= to_terms) return *this;
    Numeric r = *this;
    for (int i = terms; i < to_terms; ++i) r.v[i] = terms == 1 ? v[0] : 0.0;
    r.terms = to_terms;
    return r;
}

std::string type_name(const Value& value) {
    struct Namer {
        std::string operator()(const Numeric& n) const {
            if (n.terms == 1) return "a float";
            if (n.terms <= 3) return "a vector";
            return n.terms == 4 ? "a 4-term vector" : "a colour";
        }
        std::string operator()(const std::string&) const { return "a string"; }
        std::string operator()(const ObjectRef& o) const {
            return o->kind == ObjectNode::Kind::light ? "a light_source" : "an object";
        }
        std::string operator()(const Texture&) const { return "a texture"; }
        std::string operator()(const Pigment&) const { return "a pigment"; }
        std::string operator()(const Finish&) const { return "a finish"; }
        std::string operator()(const Interior&) const { return "an interior"; }
        std::string operator()(const TransformValue&) const { return "a transform"; }
        std::string operator()(const Camera&) const { return "a camera"; }
    };
    return std::visit(Namer{}, value);
}

}  // namespace rayset::tracer
