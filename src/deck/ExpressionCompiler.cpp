// The compiler of deck/Expression.hpp: lexer and recursive-descent parser that emit the flat
// stack code the interpreter (Expression.cpp) runs.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "core/Error.hpp"
#include "deck/Expression.hpp"
#include "deck/ExpressionNames.hpp"

namespace peridot {

using namespace expression;

namespace {

constexpr double kPi = 3.14159265358979323846;  // M_PI is not standard C++

// Guards the recursive-descent parser against stack overflow on pathological input.
constexpr int kMaxNesting = 200;

constexpr const char* kExpectedOperand = "expected a number, variable, function or \"(\"";

}  // namespace

class Expression::Compiler {
 public:
  Compiler(const std::string& context, Expression& out) : context_(context), out_(out) {}

  void compile() {
    lex();
    if (peek().kind == Tok::End) throw InputError(context_, "empty expression");
    if (startsStatementForm()) {
      statementMode_ = true;
      out_.localCount_ = 1;  // slot 0 is "value"
      scopes_.emplace_back();
      emit(Op::PushConst, 0, 0.0);
      emit(Op::StoreLocal, 0);
      while (peek().kind != Tok::End) statement();
      if (!valueAssigned_) {
        throw InputError(context_, "\"value\" is never assigned in \"" + out_.source_ + "\"");
      }
      emit(Op::LoadLocal, 0);
    } else {
      expression();
      accept(";");
      if (peek().kind != Tok::End) {
        const Token& t = peek();
        if (isPunct(t, ")")) fail(t.offset, "unmatched \")\"");
        fail(t.offset, "unexpected " + describe(t) + " after the expression");
      }
    }
    emit(Op::Return);
  }

  int maxDepth() const { return maxDepth_; }

 private:
  enum class Tok { Number, Ident, Punct, End };
  struct Token {
    Tok kind;
    std::string text;
    double number;
    std::size_t offset;
  };

  // ---- errors ----

  // "<what> at column <c> in "<source>" (<hint>)"
  [[noreturn]] void fail(std::size_t offset, const std::string& what,
                         const std::string& hint = "") const {
    const std::string& src = out_.source_;
    const std::string tail = hint.empty() ? "" : " (" + hint + ")";
    if (src.find('\n') == std::string::npos) {
      throw InputError(context_, what + " at column " + std::to_string(offset + 1) + " in \"" +
                                     src + "\"" + tail);
    }
    // Multi-line YAML blocks: quote only the offending line so the column means something.
    std::size_t lineStart = src.rfind('\n', offset == 0 ? 0 : offset - 1);
    lineStart = (lineStart == std::string::npos || offset == 0) ? 0 : lineStart + 1;
    std::size_t lineEnd = src.find('\n', lineStart);
    if (lineEnd == std::string::npos) lineEnd = src.size();
    const long line = std::count(src.begin(), src.begin() + lineStart, '\n') + 1;
    throw InputError(context_, what + " at line " + std::to_string(line) + ", column " +
                                   std::to_string(offset - lineStart + 1) + " in \"" +
                                   src.substr(lineStart, lineEnd - lineStart) + "\"" + tail);
  }

  static std::string describe(const Token& t) {
    switch (t.kind) {
      case Tok::Number:
        return "number \"" + t.text + "\"";
      case Tok::End:
        return "end of input";
      default:
        return "\"" + t.text + "\"";
    }
  }

  // ---- lexer ----

  void lex() {
    const std::string& s = out_.source_;
    std::size_t i = 0;
    while (true) {
      while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      if (i >= s.size()) break;
      const char c = s[i];
      if (c == '/' && i + 1 < s.size() && (s[i + 1] == '/' || s[i + 1] == '*')) {
        if (s[i + 1] == '/') {
          i = s.find('\n', i);
          if (i == std::string::npos) i = s.size();
        } else {
          const std::size_t close = s.find("*/", i + 2);
          if (close == std::string::npos) fail(i, "unterminated comment");
          i = close + 2;
        }
        continue;
      }
      if (c == '\\' && i + 1 < s.size() && (s[i + 1] == '{' || s[i + 1] == '}')) {
        ++i;  // YAML-escaped brace
        continue;
      }
      if (std::isdigit(static_cast<unsigned char>(c)) ||
          (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
        i = lexNumber(i);
        continue;
      }
      if (isIdentStart(c)) {
        std::size_t j = i;
        while (j < s.size() && isIdentChar(s[j])) ++j;
        tokens_.push_back({Tok::Ident, s.substr(i, j - i), 0.0, i});
        i = j;
        continue;
      }
      static const char* const kTwo[] = {"<=", ">=", "==", "!=", "&&",
                                         "||", "+=", "-=", "*=", "/="};
      bool matched = false;
      for (const char* p : kTwo) {
        if (s.compare(i, 2, p) == 0) {
          tokens_.push_back({Tok::Punct, p, 0.0, i});
          i += 2;
          matched = true;
          break;
        }
      }
      if (matched) continue;
      if (std::strchr("(){},;+-*/%^!<>=", c) != nullptr) {
        tokens_.push_back({Tok::Punct, std::string(1, c), 0.0, i});
        ++i;
        continue;
      }
      if (c == '&' || c == '|') {
        fail(i, std::string("unexpected \"") + c + "\"", "logical operators are \"&&\" and \"||\"");
      }
      fail(i, std::string("unexpected character \"") + c + "\"");
    }
    tokens_.push_back({Tok::End, "", 0.0, s.size()});
  }

  std::size_t lexNumber(std::size_t start) {
    const std::string& s = out_.source_;
    auto digit = [&](std::size_t k) {
      return k < s.size() && std::isdigit(static_cast<unsigned char>(s[k]));
    };
    std::size_t j = start;
    while (digit(j)) ++j;
    if (j < s.size() && s[j] == '.') {
      ++j;
      while (digit(j)) ++j;
    }
    if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
      std::size_t k = j + 1;
      if (k < s.size() && (s[k] == '+' || s[k] == '-')) ++k;
      if (digit(k)) {
        j = k;
        while (digit(j)) ++j;
      } else {
        j = k;  // "1e" or "1e+": report the whole fragment below
        while (j < s.size() && isIdentChar(s[j])) ++j;
        fail(start, "malformed number \"" + s.substr(start, j - start) + "\"");
      }
    }
    if (j < s.size() && (isIdentChar(s[j]) || s[j] == '.')) {
      std::size_t k = j;
      while (k < s.size() && (isIdentChar(s[k]) || s[k] == '.')) ++k;
      fail(start, "malformed number \"" + s.substr(start, k - start) + "\"");
    }
    // from_chars: locale-independent, unlike strtod.
    double value = 0.0;
    const auto res = std::from_chars(s.data() + start, s.data() + j, value);
    if (res.ec != std::errc() || res.ptr != s.data() + j) {
      fail(start, "number \"" + s.substr(start, j - start) + "\" is out of range");
    }
    tokens_.push_back({Tok::Number, s.substr(start, j - start), value, start});
    return j;
  }

  // ---- token helpers ----

  const Token& peek(std::size_t ahead = 0) const {
    return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)];
  }
  static bool isPunct(const Token& t, const char* p) { return t.kind == Tok::Punct && t.text == p; }
  static bool isIdent(const Token& t, const char* name) {
    return t.kind == Tok::Ident && t.text == name;
  }
  const Token& next() {
    const Token& t = peek();
    if (pos_ < tokens_.size() - 1) ++pos_;
    return t;
  }
  bool accept(const char* p) {
    if (!isPunct(peek(), p)) return false;
    next();
    return true;
  }
  // Closing bracket: at end of input point at the opener, otherwise at what was found instead.
  void expectClose(const char* close, const Token& opener) {
    if (accept(close)) return;
    const Token& t = peek();
    if (t.kind == Tok::End) {
      fail(opener.offset,
           std::string("missing \"") + close + "\" to match \"" + opener.text + "\"");
    }
    fail(t.offset, std::string("expected \"") + close + "\" but found " + describe(t));
  }
  // Lenient like most decks expect: the ";" before "}" or at the very end may be left out.
  void expectStatementEnd() {
    if (accept(";") || peek().kind == Tok::End || isPunct(peek(), "}")) return;
    fail(peek().offset, "expected \";\" but found " + describe(peek()));
  }

  // ---- emission ----

  static int stackEffect(Op op) {
    switch (op) {
      case Op::PushConst:
      case Op::LoadVar:
      case Op::LoadLocal:
        return 1;
      case Op::Neg:
      case Op::Not:
      case Op::Square:
      case Op::Call1:
      case Op::Jump:
        return 0;
      default:
        return -1;  // binary operators, Call2, StoreLocal, JumpIfFalse, Return
    }
  }
  static int operandCount(Op op) {
    switch (op) {
      case Op::Neg:
      case Op::Not:
      case Op::Square:
      case Op::Call1:
        return 1;
      case Op::Add:
      case Op::Sub:
      case Op::Mul:
      case Op::Div:
      case Op::Mod:
      case Op::Pow:
      case Op::Less:
      case Op::LessEq:
      case Op::Greater:
      case Op::GreaterEq:
      case Op::Equal:
      case Op::NotEqual:
      case Op::And:
      case Op::Or:
      case Op::Call2:
        return 2;
      default:
        return 0;  // not a pure operation: never folded
    }
  }

  void emit(Op op, std::int32_t arg = 0, double value = 0.0) {
    depth_ += stackEffect(op);
    maxDepth_ = std::max(maxDepth_, depth_);
    std::vector<Instr>& code = out_.code_;
    // Constant folding: a pure op whose operands are all literals of the current expression is
    // computed now, by the same interpreter, so folded and unfolded results cannot differ.
    const std::size_t n = static_cast<std::size_t>(operandCount(op));
    if (n > 0 && code.size() >= exprStart_ + n &&
        std::all_of(code.end() - n, code.end(),
                    [](const Instr& in) { return in.op == Op::PushConst; })) {
      Instr snippet[4] = {};
      std::copy(code.end() - n, code.end(), snippet);
      snippet[n] = {op, arg, value};
      snippet[n + 1] = {Op::Return, 0, 0.0};
      double stack[4] = {};
      const double result = run(snippet, nullptr, nullptr, stack);
      code.resize(code.size() - n);
      code.push_back({Op::PushConst, 0, result});
      return;
    }
    // "^2" is everywhere in decks and std::pow costs ~20 ns; x*x is exact.
    if (op == Op::Pow && code.size() > exprStart_ && code.back().op == Op::PushConst &&
        code.back().value == 2.0) {
      code.back() = {Op::Square, 0, 0.0};
      return;
    }
    // Right operand a lone constant or variable: fuse it in, saving a dispatch and a spill.
    if (code.size() > exprStart_) {
      if (const Op fused = fuse(op, code.back().op); fused != op) {
        code.back().op = fused;  // keeps the operand's value / arg
        return;
      }
    }
    code.push_back({op, arg, value});
  }
  static Op fuse(Op op, Op operand) {
    const bool k = operand == Op::PushConst;
    const bool v = operand == Op::LoadVar;
    if (!k && !v) return op;
    switch (op) {
      case Op::Add:
        return k ? Op::AddK : Op::AddV;
      case Op::Sub:
        return k ? Op::SubK : Op::SubV;
      case Op::Mul:
        return k ? Op::MulK : Op::MulV;
      case Op::Div:
        return k ? Op::DivK : Op::DivV;
      default:
        return op;
    }
  }
  std::size_t here() const { return out_.code_.size(); }
  void patch(std::size_t at) { out_.code_[at].arg = static_cast<std::int32_t>(here()); }

  // ---- statements ----

  bool startsStatementForm() const {
    const Token& t = peek();
    if (isPunct(t, "{")) return true;
    if (t.kind != Tok::Ident) return false;
    if (isKeyword(t.text) || isOtherType(t.text)) return true;
    const Token& u = peek(1);
    return isPunct(u, "=") || isPunct(u, "+=") || isPunct(u, "-=") || isPunct(u, "*=") ||
           isPunct(u, "/=");
  }

  struct NestingGuard {
    Compiler& c;
    explicit NestingGuard(Compiler& compiler) : c(compiler) {
      if (++c.nesting_ > kMaxNesting) c.fail(c.peek().offset, "nested too deeply");
    }
    ~NestingGuard() { --c.nesting_; }
  };

  void statement() {
    NestingGuard guard(*this);
    const Token& t = peek();
    if (accept(";")) return;
    if (isPunct(t, "{")) return block();
    if (isPunct(t, "}")) fail(t.offset, "unmatched \"}\"");
    if (t.kind == Tok::Ident) {
      if (t.text == "if") return ifStatement();
      if (t.text == "else") fail(t.offset, "\"else\" without a matching \"if\"");
      if (t.text == "double") return declaration();
      if (isOtherType(t.text)) {
        fail(t.offset, "unsupported type \"" + t.text + "\"", "locals are declared \"double\"");
      }
      const Token& u = peek(1);
      if (u.kind == Tok::Punct &&
          (u.text == "=" || u.text == "+=" || u.text == "-=" || u.text == "*=" || u.text == "/=")) {
        return assignment();
      }
    }
    fail(t.offset, "expected a statement but found " + describe(t),
         "an assignment, \"double\" declaration or \"if\"; a bare expression is only allowed as "
         "the whole input");
  }

  void block() {
    const Token& open = next();
    scopes_.emplace_back();
    while (!isPunct(peek(), "}")) {
      if (peek().kind == Tok::End) expectClose("}", open);
      statement();
    }
    next();
    scopes_.pop_back();
  }

  void ifStatement() {
    next();  // "if"
    const Token& open = peek();
    if (!accept("(")) fail(open.offset, "expected \"(\" after \"if\" but found " + describe(open));
    expression();
    expectClose(")", open);
    const std::size_t skipThen = here();
    emit(Op::JumpIfFalse);
    scopedStatement();
    if (isIdent(peek(), "else")) {
      next();
      const std::size_t skipElse = here();
      emit(Op::Jump);
      patch(skipThen);
      scopedStatement();
      patch(skipElse);
    } else {
      patch(skipThen);
    }
  }

  // An unbraced branch gets its own scope too, so "if (c) double a = 1;" cannot leak "a".
  void scopedStatement() {
    scopes_.emplace_back();
    statement();
    scopes_.pop_back();
  }

  void declaration() {
    next();  // "double"
    do {
      const Token& name = next();
      if (name.kind != Tok::Ident) {
        fail(name.offset, "expected a variable name after \"double\" but found " + describe(name));
      }
      if (isKeyword(name.text) || isConstantName(name.text) || name.text == "value" ||
          findFunction(name.text) >= 0 || isOtherType(name.text)) {
        fail(name.offset, "\"" + name.text + "\" is reserved and cannot be declared");
      }
      if (findVariable(name.text) >= 0) {
        fail(name.offset, "\"" + name.text + "\" is an input variable and cannot be redeclared");
      }
      if (findLocal(name.text) >= 0) fail(name.offset, "\"" + name.text + "\" is already declared");
      if (accept("=")) {
        expression();  // before the name is in scope: "double a = a;" is an error
      } else {
        emit(Op::PushConst, 0, 0.0);
      }
      const int slot = out_.localCount_++;
      emit(Op::StoreLocal, slot);
      scopes_.back().emplace_back(name.text, slot);
    } while (accept(","));
    expectStatementEnd();
  }

  void assignment() {
    const Token& name = next();
    const Token& op = next();
    const int slot = findLocal(name.text);
    if (slot < 0) {
      if (findVariable(name.text) >= 0) {
        fail(name.offset, "cannot assign to input variable \"" + name.text + "\"");
      }
      if (isConstantName(name.text)) fail(name.offset, "cannot assign to \"" + name.text + "\"");
      fail(name.offset, "assignment to undeclared variable \"" + name.text + "\"",
           "declare it with \"double " + name.text + "\"");
    }
    if (op.text != "=") emit(Op::LoadLocal, slot);
    expression();
    if (op.text == "+=") emit(Op::Add);
    if (op.text == "-=") emit(Op::Sub);
    if (op.text == "*=") emit(Op::Mul);
    if (op.text == "/=") emit(Op::Div);
    emit(Op::StoreLocal, slot);
    if (slot == 0) valueAssigned_ = true;
    expectStatementEnd();
  }

  int findLocal(const std::string& name) const {
    for (auto s = scopes_.rbegin(); s != scopes_.rend(); ++s) {
      for (const auto& [n, slot] : *s) {
        if (n == name) return slot;
      }
    }
    if (statementMode_ && name == "value") return 0;
    return -1;
  }
  int findVariable(const std::string& name) const {
    const auto& v = out_.variables_;
    const auto it = std::find(v.begin(), v.end(), name);
    return it == v.end() ? -1 : static_cast<int>(it - v.begin());
  }

  // ---- expressions (C precedence, plus "^" above unary) ----

  void expression() {
    exprStart_ = here();
    logicalOr();
  }
  void logicalOr() {
    logicalAnd();
    while (accept("||")) {
      logicalAnd();
      emit(Op::Or);
    }
  }
  void logicalAnd() {
    equality();
    while (accept("&&")) {
      equality();
      emit(Op::And);
    }
  }
  void equality() {
    relational();
    while (true) {
      if (accept("==")) {
        relational();
        emit(Op::Equal);
      } else if (accept("!=")) {
        relational();
        emit(Op::NotEqual);
      } else {
        return;
      }
    }
  }
  void relational() {
    additive();
    while (true) {
      Op op;
      if (accept("<")) {
        op = Op::Less;
      } else if (accept("<=")) {
        op = Op::LessEq;
      } else if (accept(">")) {
        op = Op::Greater;
      } else if (accept(">=")) {
        op = Op::GreaterEq;
      } else {
        return;
      }
      additive();
      emit(op);
    }
  }
  void additive() {
    multiplicative();
    while (true) {
      if (accept("+")) {
        multiplicative();
        emit(Op::Add);
      } else if (accept("-")) {
        multiplicative();
        emit(Op::Sub);
      } else {
        return;
      }
    }
  }
  void multiplicative() {
    unary();
    while (true) {
      Op op;
      if (accept("*")) {
        op = Op::Mul;
      } else if (accept("/")) {
        op = Op::Div;
      } else if (accept("%")) {
        op = Op::Mod;
      } else {
        return;
      }
      unary();
      emit(op);
    }
  }
  void unary() {
    NestingGuard guard(*this);
    if (accept("-")) {
      unary();
      emit(Op::Neg);
    } else if (accept("+")) {
      unary();
    } else if (accept("!")) {
      unary();
      emit(Op::Not);
    } else {
      power();
    }
  }
  // The exponent is a unary expression, which recurses back here: right-associative, and
  // "-2^2" parses as -(2^2) while "2^-1" still works.
  void power() {
    primary();
    if (accept("^")) {
      unary();
      emit(Op::Pow);
    }
  }
  void primary() {
    const Token& t = next();
    switch (t.kind) {
      case Tok::Number:
        emit(Op::PushConst, 0, t.number);
        return;
      case Tok::End:
        fail(t.offset, "unexpected end of input", kExpectedOperand);
      case Tok::Punct:
        if (t.text == "(") {
          logicalOr();
          expectClose(")", t);
          return;
        }
        if (t.text == ")") fail(t.offset, "unmatched \")\"");
        fail(t.offset, "unexpected " + describe(t), kExpectedOperand);
      case Tok::Ident:
        break;
    }
    if (isPunct(peek(), "(")) return call(t);
    if (isKeyword(t.text) || isOtherType(t.text)) {
      fail(t.offset, "unexpected \"" + t.text + "\" inside an expression");
    }
    if (isConstantName(t.text)) {
      emit(Op::PushConst, 0, kPi);
      return;
    }
    if (const int slot = findLocal(t.text); slot >= 0) {
      emit(Op::LoadLocal, slot);
      return;
    }
    if (const int var = findVariable(t.text); var >= 0) {
      out_.used_[static_cast<std::size_t>(var)] = true;
      emit(Op::LoadVar, var);
      return;
    }
    fail(t.offset, "unknown variable \"" + t.text + "\"");
  }
  void call(const Token& name) {
    const int f = findFunction(name.text);
    if (f < 0) fail(name.offset, "unknown function \"" + name.text + "\"");
    const Token& open = next();
    int args = 0;
    if (!isPunct(peek(), ")")) {
      do {
        logicalOr();
        ++args;
      } while (accept(","));
    }
    expectClose(")", open);
    const int arity = kFunctions[f].arity;
    if (args != arity) {
      fail(name.offset, "function \"" + name.text + "\" takes " + std::to_string(arity) +
                            (arity == 1 ? " argument" : " arguments") + ", got " +
                            std::to_string(args));
    }
    emit(arity == 1 ? Op::Call1 : Op::Call2, f);
  }

  const std::string& context_;
  Expression& out_;
  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  std::vector<std::vector<std::pair<std::string, int>>> scopes_;
  bool statementMode_ = false;
  bool valueAssigned_ = false;
  std::size_t exprStart_ = 0;  // folding must not reach into a previous statement
  int depth_ = 0;
  int maxDepth_ = 0;
  int nesting_ = 0;
};

int Expression::compileInto(const std::string& context) {
  Compiler compiler(context, *this);
  compiler.compile();
  return compiler.maxDepth();
}

}  // namespace peridot
