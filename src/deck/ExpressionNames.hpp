#pragma once
// The names of the expression language (deck/Expression.hpp): its functions, keywords, constants
// and identifiers, shared by the compiler (ExpressionCompiler.cpp) and the interpreter
// (Expression.cpp).
#include <string>
#include <vector>

namespace peridot {
namespace expression {

using Fn1 = double (*)(double);
using Fn2 = double (*)(double, double);

struct Function {
  const char* name;
  int arity;
  Fn1 f1;
  Fn2 f2;
};

// The functions a deck may call, by name; a call instruction holds the index.
extern const Function kFunctions[];
extern const int kFunctionCount;
int findFunction(const std::string& name);  // -1 if none

bool isKeyword(const std::string& s);
bool isConstantName(const std::string& s);
bool isOtherType(const std::string& s);  // C types RTCompiler decks might use
bool isIdentStart(char c);
bool isIdentChar(char c);
bool isIdentifier(const std::string& s);
// Names handed in by the caller; a bad list is a programming error, not the deck's fault.
void validateVariables(const std::vector<std::string>& variables);

}  // namespace expression
}  // namespace peridot
