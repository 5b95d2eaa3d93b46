// Identifier scopes (symbol_table.h) and the rules of #declare and #local over them: #local
// creates or assigns in the current table; #declare assigns to the most local existing
// version, or creates a global one.
// A macro parameter passed as a lone identifier is that identifier's own entry, so assigning
// to the parameter (with either directive) assigns to the caller's identifier.
#include <fmt/format.h>

#include "tracer/scene_language/parser.h"
#include "tracer/scene_language/symbol_table.h"

namespace rayset::tracer {

const SymbolRef SymbolTable::kNone;

std::vector<SymbolTable::Binding>* SymbolTable::bindings_of(NameId name) {
    if (name >= by_name_.size()) by_name_.resize(name + 1);
    return &by_name_[name];
}

const SymbolRef& SymbolTable::find(NameId name) const {
    if (name >= by_name_.size() || by_name_[name].empty()) return kNone;
    return by_name_[name].back().symbol;
}

const SymbolRef& SymbolTable::find_in_scope(NameId name, size_t scope) const {
    if (name >= by_name_.size()) return kNone;
    for (const Binding& binding : by_name_[name])
        if (binding.scope == scope) return binding.symbol;
    return kNone;
}

void SymbolTable::bind(NameId name, SymbolRef symbol, size_t scope_index) {
    std::vector<Binding>& bindings = *bindings_of(name);
    const uint32_t scope = static_cast<uint32_t>(scope_index);
    // Bindings are ordered by scope: the new one goes above those of outer scopes.
    auto place = bindings.begin();
    while (place != bindings.end() && place->scope < scope) ++place;
    if (place != bindings.end() && place->scope == scope) {
        place->symbol = std::move(symbol);
        return;
    }
    bindings.insert(place, Binding{std::move(symbol), scope});
    scope_names_[scope].push_back(name);
}

void SymbolTable::pop_scope() {
    const uint32_t scope = static_cast<uint32_t>(depth());
    for (NameId name : scope_names_.back()) {
        std::vector<Binding>& bindings = by_name_[name];
        if (!bindings.empty() && bindings.back().scope == scope)
            bindings.pop_back();  // else #undef took it
    }
    scope_names_.pop_back();
}

bool SymbolTable::unbind_most_local(NameId name) {
    std::vector<Binding>& bindings = *bindings_of(name);
    if (bindings.empty()) return false;
    bindings.pop_back();
    return true;
}

void SymbolTable::unbind_everywhere(NameId name) { bindings_of(name)->clear(); }

SymbolRef Parser::lookup(NameId name) const { return symbols_.find(name); }

void Parser::check_declarable(const Token& at, NameId name, const char* directive) {
    if (is_keyword(name))
        fail(at,
             fmt::format("cannot #{} '{}': it is a reserved word", directive, names_.text(name)));
}

void Parser::assign(const Token& at, NameId name, Value value, bool local,
                    const std::string& deprecation, bool warn_once, size_t scope) {
    // #local binds in the scope of the directive (a macro called in its value has its own,
    // gone by the time the value is assigned).
    if (scope == kInnermostScope) scope = symbols_.depth();
    const SymbolRef& existing = local ? symbols_.find_in_scope(name, scope) : symbols_.find(name);
    if (existing) {
        if (std::holds_alternative<FunctionRef>(existing->value) &&
            std::holds_alternative<FunctionRef>(value))
            fail(at, fmt::format("'{}' is already a function: #undef it before declaring it again "
                                 "(as POV-Ray requires)",
                                 names_.text(name)));
        existing->value = as_stored(std::move(value));
        if (!deprecation.empty())
            existing->deprecation = deprecation, existing->warn_once = warn_once;
        return;
    }
    auto entry = std::make_shared<SymbolEntry>();
    entry->value = as_stored(std::move(value));
    entry->deprecation = deprecation;
    entry->warn_once = warn_once;
    symbols_.bind(name, std::move(entry), local ? scope : 0);
}

Value* Parser::array_element(const Token& at, Array& array, bool for_assignment) {
    size_t index = 0;
    for (size_t d = 0; d < array.sizes.size(); ++d) {
        const Token open = expect(
            Symbol::lbracket,
            fmt::format("for index {} of the {}-dimensional array", d + 1, array.sizes.size()));
        const Token at_index = peek();
        const double raw = parse_expression().v[0];
        expect(Symbol::rbracket,
               [&] { return fmt::format("to close '[' opened at {}", location_of(open).str()); });
        // Checked as a float: a huge or NaN index has no integer to truncate to.
        if (!(raw >= 0 && raw < double(array.sizes[d])))
            fail(at_index,
                 fmt::format("array index {} out of range: dimension {} has {} elements (0 to {})",
                             raw, d + 1, array.sizes[d], array.sizes[d] - 1));
        index = index * array.sizes[d] + static_cast<size_t>(raw);  // POV-Ray truncates
    }
    Value& element = array.elements[index];
    if (!for_assignment && std::holds_alternative<std::monostate>(element))
        fail(at, "array element not yet assigned (test it with #ifdef or defined() first)");
    return &element;
}

}  // namespace rayset::tracer
