#include "deck/Expression.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "core/Error.hpp"
#include "deck/ExpressionNames.hpp"

namespace peridot {

using namespace expression;

Expression::Expression(const std::string& source, const std::vector<std::string>& variables,
                       const std::string& context)
    : source_(source), variables_(variables), used_(variables.size(), false) {
  validateVariables(variables);
  const int depth = compileInto(context);
  // +1: the interpreter keeps the top of stack in a register and spills one slot on first push.
  scratch_.assign(static_cast<std::size_t>(localCount_ + depth + 1), 0.0);
  constant_ = std::none_of(used_.begin(), used_.end(), [](bool u) { return u; });
  if (constant_)
    constantValue_ = run(code_.data(), nullptr, scratch_.data(), scratch_.data() + localCount_);
}

double Expression::evaluate(const double* variableValues) const {
  if (constant_) return constantValue_;
  double* s = scratch_.data();
  return run(code_.data(), variableValues, s, s + localCount_);
}

bool Expression::usesVariable(const std::string& name) const {
  const auto it = std::find(variables_.begin(), variables_.end(), name);
  return it != variables_.end() && used_[static_cast<std::size_t>(it - variables_.begin())];
}

// Top of stack lives in `top`; `sp` points one past the spilled values below it.
double Expression::run(const Instr* code, const double* vars, double* locals, double* stack) {
  double top = 0.0;
  double* sp = stack;
  std::size_t pc = 0;
  while (true) {
    const Instr& in = code[pc++];
    switch (in.op) {
      case Op::PushConst:
        *sp++ = top;
        top = in.value;
        break;
      case Op::LoadVar:
        *sp++ = top;
        top = vars[in.arg];
        break;
      case Op::LoadLocal:
        *sp++ = top;
        top = locals[in.arg];
        break;
      case Op::StoreLocal:
        locals[in.arg] = top;
        top = *--sp;
        break;
      case Op::Neg:
        top = -top;
        break;
      case Op::Square:
        top = top * top;
        break;
      case Op::Not:
        top = top == 0.0 ? 1.0 : 0.0;
        break;
      case Op::Add:
        top = *--sp + top;
        break;
      case Op::Sub:
        top = *--sp - top;
        break;
      case Op::Mul:
        top = *--sp * top;
        break;
      case Op::Div:
        top = *--sp / top;
        break;
      case Op::Mod:
        top = std::fmod(*--sp, top);
        break;
      case Op::Pow:
        top = std::pow(*--sp, top);
        break;
      case Op::Less:
        top = *--sp < top ? 1.0 : 0.0;
        break;
      case Op::LessEq:
        top = *--sp <= top ? 1.0 : 0.0;
        break;
      case Op::Greater:
        top = *--sp > top ? 1.0 : 0.0;
        break;
      case Op::GreaterEq:
        top = *--sp >= top ? 1.0 : 0.0;
        break;
      case Op::Equal:
        top = *--sp == top ? 1.0 : 0.0;
        break;
      case Op::NotEqual:
        top = *--sp != top ? 1.0 : 0.0;
        break;
      case Op::And: {
        const double a = *--sp;
        top = (a != 0.0 && top != 0.0) ? 1.0 : 0.0;
        break;
      }
      case Op::Or: {
        const double a = *--sp;
        top = (a != 0.0 || top != 0.0) ? 1.0 : 0.0;
        break;
      }
      case Op::Call1:
        top = kFunctions[in.arg].f1(top);
        break;
      case Op::Call2: {
        const double a = *--sp;
        top = kFunctions[in.arg].f2(a, top);
        break;
      }
      case Op::Jump:
        pc = static_cast<std::size_t>(in.arg);
        break;
      case Op::JumpIfFalse: {
        const bool taken = top == 0.0;
        top = *--sp;
        if (taken) pc = static_cast<std::size_t>(in.arg);
        break;
      }
      case Op::Return:
        return top;
      case Op::AddK:
        top += in.value;
        break;
      case Op::SubK:
        top -= in.value;
        break;
      case Op::MulK:
        top *= in.value;
        break;
      case Op::DivK:
        top /= in.value;
        break;
      case Op::AddV:
        top += vars[in.arg];
        break;
      case Op::SubV:
        top -= vars[in.arg];
        break;
      case Op::MulV:
        top *= vars[in.arg];
        break;
      case Op::DivV:
        top /= vars[in.arg];
        break;
    }
  }
}

Expression parseNumberOrExpression(const std::string& text,
                                   const std::vector<std::string>& variables,
                                   const std::string& context) {
  const auto blank = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  const auto first = std::find_if_not(text.begin(), text.end(), blank);
  const auto last = std::find_if_not(text.rbegin(), text.rend(), blank).base();
  if (first < last) {
    const char* b = &*first;
    const char* e = b + (last - first);
    const char* digits = (*b == '-' || *b == '+') ? b + 1 : b;
    // Only digits or "." may follow the sign: from_chars would also take "inf" and "nan".
    double value = 0.0;
    if (digits < e && (std::isdigit(static_cast<unsigned char>(*digits)) || *digits == '.')) {
      const auto res = std::from_chars(digits, e, value);
      if (res.ec == std::errc() && res.ptr == e) {
        validateVariables(variables);
        Expression c;
        c.source_ = text;
        c.variables_ = variables;
        c.used_.assign(variables.size(), false);
        c.constant_ = true;
        c.constantValue_ = *b == '-' ? -value : value;
        c.code_ = {{Expression::Op::PushConst, 0, c.constantValue_},
                   {Expression::Op::Return, 0, 0.0}};
        c.scratch_.assign(2, 0.0);
        return c;
      }
    }
  }
  return Expression(text, variables, context);
}

}  // namespace peridot
