// Identifier scopes as POV-Ray's reference manual states them ("Identifier Name Collisions"):
// one table for the main file (global), one more for each include file and macro call in
// progress; referencing finds the most local version. Each name keeps the stack of its
// bindings, innermost last, so that finding one costs a single index however deep the scopes.
#pragma once

#include <cstdint>
#include <vector>

#include "tracer/scene_language/values.h"

namespace rayset::tracer {

class SymbolTable {
public:
    SymbolTable() { scope_names_.emplace_back(); }  // the global scope

    void push_scope() { scope_names_.emplace_back(); }
    void pop_scope();  // the innermost scope, with every binding made in it
    size_t depth() const { return scope_names_.size() - 1; }  // 0: only the global scope

    // The most local binding of `name`, or null.
    const SymbolRef& find(NameId name) const;
    // `name`'s binding in scope `scope` (0: global), or null.
    const SymbolRef& find_in_scope(NameId name, size_t scope) const;
    // Binds `name` in scope `scope` (0: global; depth(): the innermost), hiding the bindings of
    // outer scopes and under those of inner ones, replacing a binding the same scope has.
    void bind(NameId name, SymbolRef symbol, size_t scope);
    // Removes the most local binding (#undef); false when there is none.
    bool unbind_most_local(NameId name);
    // Removes every binding of `name` (a file handle closing, a macro redefined).
    void unbind_everywhere(NameId name);

private:
    struct Binding {
        SymbolRef symbol;
        uint32_t scope;
    };
    std::vector<Binding>* bindings_of(NameId name);

    std::vector<std::vector<Binding>> by_name_;     // indexed by NameId
    std::vector<std::vector<NameId>> scope_names_;  // per scope, the names bound in it

public:
    static const SymbolRef kNone;
};

}  // namespace rayset::tracer
