#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/Error.hpp"
#include "deck/Expression.hpp"

namespace peridot {
namespace {

const std::vector<std::string> kXYZT = {"x", "y", "z", "t"};
constexpr double kPi = 3.14159265358979323846;

// Evaluates `source` with x, y, z, t bound to the given values.
double eval(const std::string& source, double x = 0, double y = 0, double z = 0, double t = 0) {
  const double v[] = {x, y, z, t};
  return Expression(source, kXYZT).evaluate(v);
}

// The InputError text for compiling `source`, or "" if it compiled.
std::string errorOf(const std::string& source, const std::string& context = "BC 1 -> Value") {
  try {
    Expression e(source, kXYZT, context);
  } catch (const InputError& err) {
    return err.what();
  }
  return "";
}

#define EXPECT_CONTAINS(text, part) \
  EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

TEST(Expression, ArithmeticAndPrecedence) {
  EXPECT_DOUBLE_EQ(eval("1+2*3"), 7.0);
  EXPECT_DOUBLE_EQ(eval("(1+2)*3"), 9.0);
  EXPECT_DOUBLE_EQ(eval("10-4-3"), 3.0);  // left-associative
  EXPECT_DOUBLE_EQ(eval("24/4/2"), 3.0);
  EXPECT_DOUBLE_EQ(eval("7 % 3"), 1.0);
  EXPECT_DOUBLE_EQ(eval("-7 % 3"), -1.0);  // fmod semantics
  EXPECT_DOUBLE_EQ(eval("2*-3"), -6.0);
  EXPECT_DOUBLE_EQ(eval("-x + +y", 3, 5), 2.0);
  EXPECT_DOUBLE_EQ(eval("- -x", 3), 3.0);
  EXPECT_DOUBLE_EQ(eval("x*y+z/t", 2, 3, 8, 4), 8.0);
  EXPECT_DOUBLE_EQ(eval("x - y*z", 1, 2, 3), -5.0);
  // Operand order when a constant or variable is the right-hand side.
  EXPECT_DOUBLE_EQ(eval("x - 2", 5), 3.0);
  EXPECT_DOUBLE_EQ(eval("2 - x", 5), -3.0);
  EXPECT_DOUBLE_EQ(eval("x - y", 5, 2), 3.0);
  EXPECT_DOUBLE_EQ(eval("x / 4", 2), 0.5);
  EXPECT_DOUBLE_EQ(eval("1 / x", 4), 0.25);
  EXPECT_DOUBLE_EQ(eval("x / y", 1, 4), 0.25);
  EXPECT_DOUBLE_EQ(eval("x + 1 + y", 1, 4), 6.0);
  EXPECT_DOUBLE_EQ(eval("x * 3 * y", 2, 4), 24.0);
}

TEST(Expression, ComparisonsAndLogicGiveOneOrZero) {
  EXPECT_EQ(eval("1 < 2"), 1.0);
  EXPECT_EQ(eval("2 < 1"), 0.0);
  EXPECT_EQ(eval("2 <= 2"), 1.0);
  EXPECT_EQ(eval("x > 2", 3), 1.0);
  EXPECT_EQ(eval("x >= 3.5", 3), 0.0);
  EXPECT_EQ(eval("x == 3", 3), 1.0);
  EXPECT_EQ(eval("x != 3", 3), 0.0);
  EXPECT_EQ(eval("1 + 2 < 4"), 1.0);    // arithmetic before comparison
  EXPECT_EQ(eval("1 < 2 == 1"), 1.0);   // relational before equality
  EXPECT_EQ(eval("1 || 0 && 0"), 1.0);  // && before ||
  EXPECT_EQ(eval("(1 || 0) && 0"), 0.0);
  EXPECT_EQ(eval("!0"), 1.0);
  EXPECT_EQ(eval("!x", 2.5), 0.0);
  EXPECT_EQ(eval("x > 1 && y > 1", 2, 2), 1.0);
  EXPECT_EQ(eval("x > 1 && y > 1", 2, 0), 0.0);
  EXPECT_EQ(eval("x > 1 || y > 1", 0, 2), 1.0);
  EXPECT_EQ(eval("2*(x<1)", 0), 2.0);
}

TEST(Expression, PowerIsRightAssociativeAndBindsTighterThanUnaryMinus) {
  EXPECT_DOUBLE_EQ(eval("2^3^2"), 512.0);
  EXPECT_DOUBLE_EQ(eval("(2^3)^2"), 64.0);
  EXPECT_DOUBLE_EQ(eval("-2^2"), -4.0);
  EXPECT_DOUBLE_EQ(eval("(-2)^2"), 4.0);
  EXPECT_DOUBLE_EQ(eval("2^-1"), 0.5);
  EXPECT_DOUBLE_EQ(eval("2*3^2"), 18.0);
  EXPECT_DOUBLE_EQ(eval("-x^2", 3), -9.0);
  EXPECT_DOUBLE_EQ(eval("x^y^z", 2, 3, 2), 512.0);  // not folded: runtime agrees
  EXPECT_DOUBLE_EQ(eval("x^2", -1.5), 2.25);        // squared without pow
  EXPECT_DOUBLE_EQ(eval("x^2^y", 3, 2), 81.0);
  EXPECT_DOUBLE_EQ(eval("x^3 + x^0.5", 4), 66.0);
}

TEST(Expression, Functions) {
  EXPECT_DOUBLE_EQ(eval("sin(pi/2)"), 1.0);
  EXPECT_DOUBLE_EQ(eval("cos(M_PI)"), -1.0);
  EXPECT_NEAR(eval("tan(pi/4)"), 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(eval("asin(1)"), kPi / 2);
  EXPECT_DOUBLE_EQ(eval("acos(-1)"), kPi);
  EXPECT_DOUBLE_EQ(eval("atan(1)"), kPi / 4);
  EXPECT_DOUBLE_EQ(eval("atan2(y, x)", -1, 1), 3 * kPi / 4);
  EXPECT_DOUBLE_EQ(eval("sinh(x)", 0.5), std::sinh(0.5));
  EXPECT_DOUBLE_EQ(eval("cosh(x)", 0.5), std::cosh(0.5));
  EXPECT_DOUBLE_EQ(eval("tanh(x)", 0.5), std::tanh(0.5));
  EXPECT_DOUBLE_EQ(eval("log(exp(x))", 2), 2.0);
  EXPECT_DOUBLE_EQ(eval("log10(1000)"), 3.0);
  EXPECT_DOUBLE_EQ(eval("sqrt(x)", 16), 4.0);
  EXPECT_DOUBLE_EQ(eval("abs(x) + fabs(y)", -2, -3), 5.0);
  EXPECT_DOUBLE_EQ(eval("pow(2, 10)"), 1024.0);
  EXPECT_DOUBLE_EQ(eval("floor(-1.5) + ceil(1.2)"), 0.0);
  EXPECT_DOUBLE_EQ(eval("min(x, y) * max(x, y)", 2, 5), 10.0);
  EXPECT_DOUBLE_EQ(eval("fmod(7.5, 2)"), 1.5);
  EXPECT_DOUBLE_EQ(eval("sqrt(x*x + y*y)", 3, 4), 5.0);
  EXPECT_DOUBLE_EQ(eval("max(min(x, 1), -1)", 7), 1.0);
}

TEST(Expression, NumberLiterals) {
  EXPECT_DOUBLE_EQ(eval("1.0e-8"), 1.0e-8);
  EXPECT_DOUBLE_EQ(eval("2E5"), 2e5);
  EXPECT_DOUBLE_EQ(eval(".5"), 0.5);
  EXPECT_DOUBLE_EQ(eval("5."), 5.0);
  EXPECT_DOUBLE_EQ(eval("1e5"), 1e5);
  EXPECT_DOUBLE_EQ(eval("1e+2"), 100.0);
  EXPECT_DOUBLE_EQ(eval("3E-2*x", 100), 3.0);
}

TEST(Expression, PeridigmExamples) {
  const double v[] = {0, 0, 0, 0};
  Expression constant("-244.939", kXYZT);
  EXPECT_TRUE(constant.isConstant());
  EXPECT_EQ(constant.evaluate(v), -244.939);

  EXPECT_NEAR(eval("0.001*y*t/1.0e-8", 0, 2.0, 0, 3.0e-8), 0.006, 1e-15);

  const std::string bc = "(200 - 50*((z/0.05)-1)^2)*cos(atan2(y,x))";
  EXPECT_NEAR(eval(bc, 1, 1, 0.1), 150.0 * std::cos(kPi / 4), 1e-12);
  EXPECT_NEAR(eval(bc, 1, 0, 0.05), 200.0, 1e-12);
  EXPECT_NEAR(eval(bc, -1, 0, 0.0), -150.0, 1e-12);

  const std::string ramp = " if(t <= 0.2){ value = 0.0; } else{ value = 1000*(t-0.2); } ";
  EXPECT_EQ(eval(ramp, 0, 0, 0, 0.1), 0.0);
  EXPECT_EQ(eval(ramp, 0, 0, 0, 0.2), 0.0);
  EXPECT_NEAR(eval(ramp, 0, 0, 0, 0.5), 300.0, 1e-12);

  EXPECT_DOUBLE_EQ(eval("value = 2*x;", 4), 8.0);
}

TEST(Expression, IfElseChains) {
  const std::string chain =
      "if (x < 0) { value = -1; } else if (x == 0) { value = 0; } else if (x < 10) { value = 1; }"
      " else { value = 2; }";
  EXPECT_EQ(eval(chain, -5), -1.0);
  EXPECT_EQ(eval(chain, 0), 0.0);
  EXPECT_EQ(eval(chain, 5), 1.0);
  EXPECT_EQ(eval(chain, 50), 2.0);

  // Without braces, and a dangling else binding to the nearest if.
  const std::string bare = "if (x > 0) if (y > 0) value = 1; else value = 2; else value = 3;";
  EXPECT_EQ(eval(bare, 1, 1), 1.0);
  EXPECT_EQ(eval(bare, 1, -1), 2.0);
  EXPECT_EQ(eval(bare, -1, 1), 3.0);

  // "value" starts at 0 when no branch assigns it.
  EXPECT_EQ(eval("if (x > 0) value = 7;", 1), 7.0);
  EXPECT_EQ(eval("if (x > 0) value = 7;", -1), 0.0);

  // YAML-escaped braces.
  const std::string escaped = "if (t < 1) \\{ value = 1; \\} else \\{ value = 2; \\}";
  EXPECT_EQ(eval(escaped, 0, 0, 0, 0.5), 1.0);
  EXPECT_EQ(eval(escaped, 0, 0, 0, 1.5), 2.0);

  // Constant conditions fold but must still branch correctly.
  EXPECT_EQ(eval("if (1) value = x; else value = 2;", 5), 5.0);
  EXPECT_EQ(eval("if (0) value = x; else value = 2;", 5), 2.0);
}

TEST(Expression, LocalsAndCompoundAssignment) {
  EXPECT_DOUBLE_EQ(eval("double a = 3.0; double b; b = a*x; value = b + 1;", 2), 7.0);
  EXPECT_DOUBLE_EQ(eval("double a = 1, b = 2, c; value = a + b + c;"), 3.0);
  EXPECT_DOUBLE_EQ(eval("double a = x; a += 1; a *= 3; a -= 2; a /= 2; value = a", 1), 2.0);
  EXPECT_DOUBLE_EQ(eval("value = x; value += 10;", 1), 11.0);
  // Block scoping: the same name in sibling blocks is fine.
  const std::string scoped =
      "if (x > 0) { double a = 1; value = a; } else { double a = 2; value = a; }";
  EXPECT_EQ(eval(scoped, 1), 1.0);
  EXPECT_EQ(eval(scoped, -1), 2.0);
  // Locals are re-initialised on every evaluation, not carried over.
  Expression e("double a; a += x; value = a;", kXYZT);
  const double v[] = {2, 0, 0, 0};
  EXPECT_EQ(e.evaluate(v), 2.0);
  EXPECT_EQ(e.evaluate(v), 2.0);
  // Comments.
  EXPECT_EQ(eval("// ramp\nvalue = /* scaled */ 2*x; // done", 3), 6.0);
}

TEST(Expression, IsConstant) {
  EXPECT_TRUE(Expression("-244.939", kXYZT).isConstant());
  EXPECT_TRUE(Expression("2*pi + sqrt(4)", kXYZT).isConstant());
  EXPECT_TRUE(Expression("double a = 2; value = a*3;", kXYZT).isConstant());
  EXPECT_FALSE(Expression("x*0", kXYZT).isConstant());
  EXPECT_FALSE(Expression("if (t > 1) value = 1;", kXYZT).isConstant());
  // A constant expression ignores its input, even a null one.
  EXPECT_DOUBLE_EQ(Expression("2*pi", kXYZT).evaluate(nullptr), 2 * kPi);
  EXPECT_DOUBLE_EQ(Expression("double a = 2; value = a*3;", {}).evaluate(nullptr), 6.0);
}

TEST(Expression, UsesVariable) {
  Expression e("0.001*y*t/1.0e-8", kXYZT);
  EXPECT_TRUE(e.usesVariable("y"));
  EXPECT_TRUE(e.usesVariable("t"));
  EXPECT_FALSE(e.usesVariable("x"));
  EXPECT_FALSE(e.usesVariable("z"));
  EXPECT_FALSE(e.usesVariable("nope"));
  Expression f("if (t < 1) value = 0; else value = x;", kXYZT);
  EXPECT_TRUE(f.usesVariable("t"));
  EXPECT_TRUE(f.usesVariable("x"));
  EXPECT_FALSE(f.usesVariable("y"));
  EXPECT_EQ(f.source(), "if (t < 1) value = 0; else value = x;");
}

TEST(Expression, OtherVariableLists) {
  Expression e("1 - zeta/horizon", {"zeta", "horizon"});
  const double v[] = {0.25, 1.0};
  EXPECT_DOUBLE_EQ(e.evaluate(v), 0.75);
  EXPECT_THROW(Expression("x", {"x", "x"}), std::invalid_argument);
  EXPECT_THROW(Expression("1", {"value"}), std::invalid_argument);
  EXPECT_THROW(Expression("1", {"2x"}), std::invalid_argument);
}

TEST(Expression, IeeeResultsSurviveConstantFolding) {
  EXPECT_TRUE(std::isinf(eval("1/0")));
  EXPECT_TRUE(std::isnan(eval("0/0")));
  EXPECT_TRUE(std::isnan(eval("sqrt(-1)")));
  EXPECT_EQ(eval("0/0 != 0/0"), 1.0);
}

TEST(Expression, ErrorUnknownVariable) {
  const std::string msg = errorOf("x+q");
  EXPECT_CONTAINS(msg, "BC 1 -> Value: ");
  EXPECT_CONTAINS(msg, "unknown variable \"q\" at column 3 in \"x+q\"");
  EXPECT_CONTAINS(errorOf("value*2"), "unknown variable \"value\"");  // only in statement form
  EXPECT_CONTAINS(errorOf("if (x) { double a = 1; } value = a;"), "unknown variable \"a\"");
}

TEST(Expression, ErrorUnknownFunction) {
  EXPECT_CONTAINS(errorOf("2*foo(x)"), "unknown function \"foo\" at column 3");
  EXPECT_CONTAINS(errorOf("sign(x)"), "unknown function \"sign\"");
}

TEST(Expression, ErrorUnbalancedParentheses) {
  EXPECT_CONTAINS(errorOf("(x+1"), "missing \")\" to match \"(\" at column 1");
  EXPECT_CONTAINS(errorOf("x+1)"), "unmatched \")\" at column 4");
  EXPECT_CONTAINS(errorOf("sin(x"), "missing \")\" to match \"(\" at column 4");
  EXPECT_CONTAINS(errorOf("((x)"), "missing \")\"");
  EXPECT_CONTAINS(errorOf("(x y)"), "expected \")\" but found \"y\" at column 4");
  EXPECT_CONTAINS(errorOf("if (x > 0 { value = 1; }"), "expected \")\" but found \"{\"");
  EXPECT_CONTAINS(errorOf("if (x > 0) { value = 1;"), "missing \"}\" to match \"{\" at column 12");
  EXPECT_CONTAINS(errorOf("value = 1; }"), "unmatched \"}\" at column 12");
}

TEST(Expression, ErrorEmpty) {
  EXPECT_CONTAINS(errorOf(""), "empty expression");
  EXPECT_CONTAINS(errorOf("   \t "), "empty expression");
  EXPECT_CONTAINS(errorOf("/* nothing */"), "empty expression");
}

TEST(Expression, ErrorTrailingGarbage) {
  EXPECT_CONTAINS(errorOf("x+1 y"), "unexpected \"y\" after the expression at column 5");
  EXPECT_CONTAINS(errorOf("2 3"), "unexpected number \"3\"");
  EXPECT_CONTAINS(errorOf("value = 2*x; x+1"), "a bare expression is only allowed");
  EXPECT_CONTAINS(errorOf("x+"), "unexpected end of input at column 3");
  EXPECT_CONTAINS(errorOf("x*/y"), "unexpected \"/\"");
  EXPECT_CONTAINS(errorOf("x # y"), "unexpected character \"#\" at column 3");
  EXPECT_CONTAINS(errorOf("x & y"), "\"&&\"");
}

TEST(Expression, ErrorWrongArity) {
  EXPECT_CONTAINS(errorOf("atan2(y)"), "function \"atan2\" takes 2 arguments, got 1 at column 1");
  EXPECT_CONTAINS(errorOf("1 + sin(x, y)"), "function \"sin\" takes 1 argument, got 2 at column 5");
  EXPECT_CONTAINS(errorOf("cos()"), "takes 1 argument, got 0");
}

TEST(Expression, ErrorStatements) {
  EXPECT_CONTAINS(errorOf("double a = x;"), "\"value\" is never assigned in \"double a = x;\"");
  EXPECT_CONTAINS(errorOf("x = 1;"), "cannot assign to input variable \"x\" at column 1");
  EXPECT_CONTAINS(errorOf("b = 1; value = b;"), "assignment to undeclared variable \"b\"");
  EXPECT_CONTAINS(errorOf("double a; double a; value = a;"), "\"a\" is already declared");
  EXPECT_CONTAINS(errorOf("double x = 1; value = x;"), "\"x\" is an input variable");
  EXPECT_CONTAINS(errorOf("double pi = 3; value = pi;"), "\"pi\" is reserved");
  EXPECT_CONTAINS(errorOf("int i = 1; value = i;"), "unsupported type \"int\"");
  EXPECT_CONTAINS(errorOf("value = 1 value = 2"), "expected \";\" but found \"value\"");
  EXPECT_EQ(eval("if (x) { value = 1 } else { value = 2 }", 1), 1.0);  // ";" before "}" optional
  EXPECT_CONTAINS(errorOf("else value = 1;"), "\"else\" without a matching \"if\"");
  EXPECT_CONTAINS(errorOf("value = 1e;"), "malformed number \"1e\" at column 9");
  EXPECT_CONTAINS(errorOf("2x"), "malformed number \"2x\"");
  EXPECT_CONTAINS(errorOf("1.2.3"), "malformed number \"1.2.3\"");
}

TEST(Expression, ErrorLocationOnMultiLineSource) {
  EXPECT_CONTAINS(errorOf("double a = 1;\nvalue = a + q;"),
                  "unknown variable \"q\" at line 2, column 13 in \"value = a + q;\"");
}

TEST(Expression, ErrorOnDeepNestingInsteadOfCrash) {
  EXPECT_CONTAINS(errorOf(std::string(100000, '(') + "x" + std::string(100000, ')')),
                  "nested too deeply");
  EXPECT_CONTAINS(errorOf(std::string(100000, '-') + "x"), "nested too deeply");
  EXPECT_DOUBLE_EQ(eval(std::string(50, '(') + "x" + std::string(50, ')'), 3), 3.0);
}

TEST(Expression, ParseNumberOrExpression) {
  Expression a = parseNumberOrExpression("  -244.939 ", kXYZT);
  EXPECT_TRUE(a.isConstant());
  EXPECT_EQ(a.evaluate(nullptr), -244.939);
  EXPECT_EQ(parseNumberOrExpression("+2e3", kXYZT).evaluate(nullptr), 2000.0);
  Expression b = parseNumberOrExpression("2*x", kXYZT, "ctx");
  EXPECT_FALSE(b.isConstant());
  const double v[] = {4, 0, 0, 0};
  EXPECT_EQ(b.evaluate(v), 8.0);
  EXPECT_THROW(parseNumberOrExpression("inf", kXYZT), InputError);
  EXPECT_THROW(parseNumberOrExpression("1e", kXYZT), InputError);
}

TEST(Expression, CopiesAreIndependent) {
  Expression a("double s = x; s *= 2; value = s;", kXYZT);
  Expression b = a;
  const double v1[] = {1, 0, 0, 0};
  const double v2[] = {5, 0, 0, 0};
  EXPECT_EQ(a.evaluate(v1), 2.0);
  EXPECT_EQ(b.evaluate(v2), 10.0);
  EXPECT_EQ(a.evaluate(v1), 2.0);
}

TEST(Expression, MillionEvaluationsAreConsistent) {
  Expression plain("(200 - 50*((z/0.05)-1)^2)*cos(atan2(y,x))", kXYZT);
  Expression statements("double r = x*x + y*y; if (t <= 0.2) { value = 0; } else { value = r*t; }",
                        kXYZT);
  const double v[] = {0.3, 0.4, 0.07, 0.5};
  const double first = plain.evaluate(v);
  const double second = statements.evaluate(v);
  EXPECT_NEAR(first, (200 - 50 * std::pow(0.07 / 0.05 - 1, 2)) * 0.6, 1e-12);
  EXPECT_NEAR(second, 0.125, 1e-15);
  long mismatches = 0;
  for (int i = 0; i < 1000000; ++i) {
    if (plain.evaluate(v) != first || statements.evaluate(v) != second) ++mismatches;
  }
  EXPECT_EQ(mismatches, 0);
}

}  // namespace
}  // namespace peridot
