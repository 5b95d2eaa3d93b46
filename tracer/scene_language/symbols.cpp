// Identifier scopes as POV-Ray's reference manual states them ("Identifier Name Collisions"):
// one table for the main file (global), one more for each include file and macro call in
// progress. Referencing finds the most local version. #local creates or assigns in the
// current table; #declare assigns to the most local existing version, or creates a global one.
// A macro parameter passed as a lone identifier is that identifier's own entry, so assigning
// to the parameter (with either directive) assigns to the caller's identifier.
#include <fmt/format.h>

#include "tracer/scene_language/parser.h"

namespace rayset::tracer {

SymbolRef Parser::lookup(NameId name) const {
    for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope) {
        auto found = scope->find(name);
        if (found != scope->end()) return found->second;
    }
    return nullptr;
}

void Parser::check_declarable(const Token& at, NameId name, const char* directive) {
    if (is_keyword(name))
        fail(at, fmt::format("cannot #{} '{}': it is a reserved word", directive, names_.text(name)));
}

void Parser::assign(const Token& at, NameId name, Value value, bool local, const std::string& deprecation,
                    bool warn_once) {
    SymbolRef existing;
    if (local) {
        auto found = scopes_.back().find(name);
        if (found != scopes_.back().end()) existing = found->second;
    } else {
        existing = lookup(name);
    }
    if (existing) {
        if (std::holds_alternative<FunctionRef>(existing->value) && std::holds_alternative<FunctionRef>(value))
            fail(at, fmt::format("'{}' is already a function: #undef it before declaring it again (as POV-Ray requires)",
                                 names_.text(name)));
        existing->value = as_stored(std::move(value));
        if (!deprecation.empty()) existing->deprecation = deprecation, existing->warn_once = warn_once;
        return;
    }
    auto entry = std::make_shared<SymbolEntry>();
    entry->value = as_stored(std::move(value));
    entry->deprecation = deprecation;
    entry->warn_once = warn_once;
    (local ? scopes_.back() : scopes_.front())[name] = std::move(entry);
}

Value* Parser::array_element(const Token& at, Array& array, bool for_assignment) {
    size_t index = 0;
    for (size_t d = 0; d < array.sizes.size(); ++d) {
        const Token open = expect(Symbol::lbracket, fmt::format("for index {} of the {}-dimensional array",
                                                                 d + 1, array.sizes.size()));
        const Token at_index = peek();
        const double raw = parse_expression().v[0];
        expect(Symbol::rbracket, fmt::format("to close '[' opened at {}", location_of(open).str()));
        const long i = static_cast<long>(raw);  // POV-Ray truncates
        if (raw < 0 || i >= array.sizes[d])
            fail(at_index, fmt::format("array index {} out of range: dimension {} has {} elements (0 to {})", raw,
                                       d + 1, array.sizes[d], array.sizes[d] - 1));
        index = index * array.sizes[d] + static_cast<size_t>(i);
    }
    Value& element = array.elements[index];
    if (!for_assignment && std::holds_alternative<std::monostate>(element))
        fail(at, "array element not yet assigned (test it with #ifdef or defined() first)");
    return &element;
}

}  // namespace rayset::tracer
