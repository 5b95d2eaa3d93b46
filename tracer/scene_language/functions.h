// User-defined functions (`function { ... }`, reference manual 3.3.1.8): float functions
// compiled from POV-Ray's function syntax into a small stack machine, and the special kinds
// (internal(N), pattern, pigment, transform and spline functions). A function is evaluated
// while parsing when a scene calls it, and later by the renderer (isosurfaces, function
// patterns), so evaluation is thread-safe and allocation-free for float functions.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "tracer/scene_language/transform.h"
#include "tracer/scene_language/values.h"

namespace rayset::tracer {

struct Pattern;

// Thrown by evaluate() for what cannot be evaluated (an internal function not implemented, a
// pattern the renderer does not have yet); the parser reports it as not supported.
class FunctionNotSupported : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class UserFunction {
public:
    enum class Kind { expression, internal, pattern, pigment, transform, spline };

    Kind kind() const { return kind_; }
    int parameter_count() const { return parameter_count_; }
    // 1 for float functions; 3 for transform functions, 5 for pigment functions, the spline's
    // terms for spline functions.
    int result_terms() const { return result_terms_; }
    Numeric evaluate(const double* arguments) const;
    // Float functions: the value at `arguments` (parameter_count() of them).
    double evaluate_float(const double* arguments) const;

    // The stack machine's instructions (public for the compiler in functions.cpp).
    enum class Op : uint8_t {
        constant,
        parameter,
        local,
        negate,
        add,
        subtract,
        multiply,
        divide,
        less,
        less_equal,
        equal,
        not_equal,
        greater_equal,
        greater,
        logical_and,
        logical_or,
        call_builtin,
        call_function,
        select3,
        select4,
        sum,
        product
    };
    struct Instruction {
        Op op;
        uint8_t argument_count = 0;  // calls
        int16_t component = -1;  // call_function: the term taken from a vector result (-2: gray)
        int32_t index = 0;       // constant, parameter, local, builtin, function, loop variable
        int32_t length = 0;      // sum / product: instructions in the loop body that follows
    };

private:
    friend class FunctionCompiler;
    friend class Parser;
    double run(const Instruction* begin, const Instruction* end, const double* parameters,
               double* locals) const;
    double call_function(const Instruction& call, const double* arguments) const;
    double run_loop(const Instruction& loop, double first, double last, const double* parameters,
                    double* locals) const;

    Kind kind_ = Kind::expression;
    int parameter_count_ = 3;
    int result_terms_ = 1;
    int local_count_ = 0;
    std::vector<Instruction> code_;
    std::vector<double> constants_;
    std::vector<FunctionRef> callees_;
    int internal_number_ = -1;
    std::shared_ptr<const Pattern> pattern_;
    PigmentRef pigment_;
    Matrix4 transform_;
    SplineRef spline_;
};

// The built-in float functions a function body may call (abs, sin, select, ...): the index
// an Instruction::call_builtin names, or -1.
int function_builtin_index(const std::string& name);

}  // namespace rayset::tracer
