// One function per alternative, for std::visit: std::visit(Overloaded{[](const A &) {…},
// [](const B &) {…}}, variant).
//
// Plain C++20, no Qt.
#pragma once

namespace hatpic {

template<typename... F> struct Overloaded : F...
{
    using F::operator()...;
};
// Spelled out for compilers without C++20's aggregate deduction (clang 14, the fuzz build's).
template<typename... F> Overloaded(F...) -> Overloaded<F...>;

} // namespace hatpic
