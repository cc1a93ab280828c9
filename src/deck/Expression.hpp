#pragma once
// User expressions in input decks (boundary-condition values, initial conditions, influence
// functions) in the C-like dialect of Peridigm's RTCompiler. Compiled once into a flat stack
// bytecode so per-point, per-step evaluation is a short loop with no allocation.
//
// Dialect:
//  - Plain form: a single expression, e.g. "(200 - 50*((z/0.05)-1)^2)*cos(atan2(y,x))",
//    optionally followed by ";". It is the value.
//  - Statement form (chosen when the input starts with an assignment, "double", "if" or "{"):
//    statements separated by ";" that must assign the output "value" somewhere:
//      value = expr;   local = expr;   local += expr;  (also -=, *=, /=)
//      double a = 3.0, b;   (locals are block scoped; no initialiser means 0)
//      if (cond) stmt [else stmt]   with or without { } blocks; else-if chains.
//    "value" starts at 0 on every evaluation. A ";" before "}" or at the end may be omitted.
//    "\{" and "\}" (escaped braces from YAML) are read as "{" and "}". // and /* */ comments.
//  - Operators, tightest first: "^" (power, right-associative, and tighter than unary minus as
//    in mathematics: -2^2 == -4, 2^3^2 == 512, 2^-1 == 0.5); unary + - !; * / % (% is fmod);
//    + -; < <= > >=; == !=; &&; ||. Comparisons and logic give 1.0 or 0.0; any nonzero
//    (including NaN) is true, as in C. && and || evaluate both sides (nothing has side effects).
//  - Functions: sin cos tan asin acos atan sinh cosh tanh exp log log10 sqrt abs fabs floor ceil
//    (abs is fabs), atan2(y,x) pow(a,b) min(a,b) max(a,b) fmod(a,b) (min/max are fmin/fmax).
//  - Constants: pi and M_PI. "e" is not reserved; 1e5, 2E5, 1.0e-8, .5 and 5. are numbers.
#include <cstdint>
#include <string>
#include <vector>

namespace peridot {

class Expression {
 public:
  // `variables` are the names the expression may read, in the order evaluate() receives them.
  // Throws InputError(context, ...) for anything wrong in `source`; throws std::invalid_argument
  // if `variables` itself is bad (not identifiers, duplicated, or reserved), a caller bug.
  Expression(const std::string& source, const std::vector<std::string>& variables,
             const std::string& context = "");

  // `variableValues` holds one value per name given to the constructor (may be null when
  // isConstant()). Does not allocate. Not thread-safe: the object owns the scratch space the
  // bytecode runs in, so give each thread its own copy (copies are independent and cheap).
  double evaluate(const double* variableValues) const;

  // True if no variable is read anywhere; evaluate() then returns a value computed at compile time.
  bool isConstant() const { return constant_; }
  // Whether `name` (one of the constructor's variables) is read anywhere in the source.
  bool usesVariable(const std::string& name) const;
  const std::string& source() const { return source_; }

 private:
  class Compiler;
  // Compiles `source_` into code_ (ExpressionCompiler.cpp); returns the stack depth it needs.
  int compileInto(const std::string& context);
  friend Expression parseNumberOrExpression(const std::string&, const std::vector<std::string>&,
                                            const std::string&);

  enum class Op : std::uint8_t {
    PushConst,
    LoadVar,
    LoadLocal,
    StoreLocal,
    Neg,
    Not,
    Square,
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    Pow,
    Less,
    LessEq,
    Greater,
    GreaterEq,
    Equal,
    NotEqual,
    And,
    Or,
    Call1,
    Call2,
    Jump,
    JumpIfFalse,
    Return,
    // Binary op whose right operand is Instr::value (K) or variable Instr::arg (V).
    AddK,
    SubK,
    MulK,
    DivK,
    AddV,
    SubV,
    MulV,
    DivV
  };
  struct Instr {
    Op op;
    std::int32_t arg;  // variable/local slot, function index or jump target
    double value;      // PushConst and the K ops
  };

  Expression() = default;
  static double run(const Instr* code, const double* vars, double* locals, double* stack);

  std::string source_;
  std::vector<std::string> variables_;
  std::vector<bool> used_;  // per variable
  std::vector<Instr> code_;
  int localCount_ = 0;
  bool constant_ = false;
  double constantValue_ = 0.0;
  mutable std::vector<double> scratch_;  // locals, then the operand stack
};

// For deck entries that are usually a plain number: a string that is exactly one number (after
// trimming blanks) skips the compiler and yields a constant Expression; anything else is compiled.
Expression parseNumberOrExpression(const std::string& text,
                                   const std::vector<std::string>& variables,
                                   const std::string& context = "");

}  // namespace peridot
