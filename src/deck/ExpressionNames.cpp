#include "deck/ExpressionNames.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace peridot {
namespace expression {

// Lambdas rather than &std::sin: the std overloads cannot be named as one pointer portably.
const Function kFunctions[] = {
    {"sin", 1, [](double a) { return std::sin(a); }, nullptr},
    {"cos", 1, [](double a) { return std::cos(a); }, nullptr},
    {"tan", 1, [](double a) { return std::tan(a); }, nullptr},
    {"asin", 1, [](double a) { return std::asin(a); }, nullptr},
    {"acos", 1, [](double a) { return std::acos(a); }, nullptr},
    {"atan", 1, [](double a) { return std::atan(a); }, nullptr},
    {"sinh", 1, [](double a) { return std::sinh(a); }, nullptr},
    {"cosh", 1, [](double a) { return std::cosh(a); }, nullptr},
    {"tanh", 1, [](double a) { return std::tanh(a); }, nullptr},
    {"exp", 1, [](double a) { return std::exp(a); }, nullptr},
    {"log", 1, [](double a) { return std::log(a); }, nullptr},
    {"log10", 1, [](double a) { return std::log10(a); }, nullptr},
    {"sqrt", 1, [](double a) { return std::sqrt(a); }, nullptr},
    {"abs", 1, [](double a) { return std::fabs(a); }, nullptr},
    {"fabs", 1, [](double a) { return std::fabs(a); }, nullptr},
    {"floor", 1, [](double a) { return std::floor(a); }, nullptr},
    {"ceil", 1, [](double a) { return std::ceil(a); }, nullptr},
    {"atan2", 2, nullptr, [](double a, double b) { return std::atan2(a, b); }},
    {"pow", 2, nullptr, [](double a, double b) { return std::pow(a, b); }},
    {"min", 2, nullptr, [](double a, double b) { return std::fmin(a, b); }},
    {"max", 2, nullptr, [](double a, double b) { return std::fmax(a, b); }},
    {"fmod", 2, nullptr, [](double a, double b) { return std::fmod(a, b); }},
};
const int kFunctionCount = static_cast<int>(sizeof(kFunctions) / sizeof(kFunctions[0]));

int findFunction(const std::string& name) {
  for (int i = 0; i < kFunctionCount; ++i) {
    if (name == kFunctions[i].name) return i;
  }
  return -1;
}

bool isKeyword(const std::string& s) { return s == "if" || s == "else" || s == "double"; }
bool isConstantName(const std::string& s) { return s == "pi" || s == "M_PI"; }
// C types RTCompiler decks might use; we only do double, and say so instead of "unknown variable".
bool isOtherType(const std::string& s) {
  return s == "int" || s == "float" || s == "long" || s == "char" || s == "bool" || s == "auto" ||
         s == "unsigned" || s == "short" || s == "const";
}
bool isIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentifier(const std::string& s) {
  return !s.empty() && isIdentStart(s[0]) && std::all_of(s.begin(), s.end(), isIdentChar);
}

// Names handed in by the caller; a bad list is a programming error, not the deck's fault.
void validateVariables(const std::vector<std::string>& variables) {
  for (auto it = variables.begin(); it != variables.end(); ++it) {
    if (!isIdentifier(*it) || isKeyword(*it) || isConstantName(*it) || *it == "value" ||
        std::find(variables.begin(), it, *it) != it) {
      throw std::invalid_argument("Expression: bad or duplicate variable name \"" + *it + "\"");
    }
  }
}

}  // namespace expression
}  // namespace peridot
