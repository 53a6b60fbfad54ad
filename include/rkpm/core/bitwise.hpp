#pragma once
// bitwise_value<T>: a value whose object bytes are the whole value, so that copying the bytes
// out and back (a checkpoint, io/checkpoint.hpp) restores it bit for bit. True for trivially
// copyable types; for fixed-size Eigen matrices of such (their copy constructor is user-written,
// so the standard trait says no, but their storage is a plain array); and for aggregates of up
// to 8 members (the material states, contact pairs) whose members all are. Members are found by
// aggregate initialization and structured bindings (no reflection in C++20). Padding bytes
// (contact_pair has 8, after its 16-byte aligned vec2 members) are copied as they are: they are
// never read as values, but two files of one state need not be byte-identical.

#include <Eigen/Core>
#include <cstddef>
#include <type_traits>
#include <utility>

namespace rkpm {

namespace detail {

template <class T>
struct bitwise_matrix : std::false_type {};
template <class S, int R, int C, int O, int MR, int MC>
struct bitwise_matrix<Eigen::Matrix<S, R, C, O, MR, MC>>
    : std::bool_constant<(R > 0 && C > 0 && std::is_trivially_copyable_v<S>)> {};

struct any_member {
  template <class U>
  operator U() const;  // declared only: used in unevaluated aggregate initialization
};

// Number of members of an aggregate T (counted by initializing it with more and more values).
template <class T, class... A>
constexpr std::size_t member_count() {
  if constexpr (sizeof...(A) <= 8 && requires { T{A{}..., any_member{}}; })
    return member_count<T, A..., any_member>();
  else
    return sizeof...(A);
}

template <class T>
constexpr bool bitwise_leaf() {
  return std::is_trivially_copyable_v<T> || bitwise_matrix<T>::value;
}

template <class... M>
struct members {};

// The member types of an aggregate (only used inside decltype).
template <class T>
auto member_types(const T& t) {
  constexpr std::size_t n = member_count<T>();
#define RKPM_MEMBERS(N, ...)                  \
  if constexpr (n == N) {                     \
    auto& [__VA_ARGS__] = t;                  \
    return members<RKPM_DECLTYPES(__VA_ARGS__)>{}; \
  }
#define RKPM_DECLTYPES(...) RKPM_DECLTYPES_N(__VA_ARGS__, 8, 7, 6, 5, 4, 3, 2, 1)(__VA_ARGS__)
#define RKPM_DECLTYPES_N(_1, _2, _3, _4, _5, _6, _7, _8, N, ...) RKPM_DECLTYPES_##N
#define RKPM_DECLTYPES_1(a) decltype(a)
#define RKPM_DECLTYPES_2(a, ...) decltype(a), RKPM_DECLTYPES_1(__VA_ARGS__)
#define RKPM_DECLTYPES_3(a, ...) decltype(a), RKPM_DECLTYPES_2(__VA_ARGS__)
#define RKPM_DECLTYPES_4(a, ...) decltype(a), RKPM_DECLTYPES_3(__VA_ARGS__)
#define RKPM_DECLTYPES_5(a, ...) decltype(a), RKPM_DECLTYPES_4(__VA_ARGS__)
#define RKPM_DECLTYPES_6(a, ...) decltype(a), RKPM_DECLTYPES_5(__VA_ARGS__)
#define RKPM_DECLTYPES_7(a, ...) decltype(a), RKPM_DECLTYPES_6(__VA_ARGS__)
#define RKPM_DECLTYPES_8(a, ...) decltype(a), RKPM_DECLTYPES_7(__VA_ARGS__)
  RKPM_MEMBERS(1, a)
  else RKPM_MEMBERS(2, a, b)
  else RKPM_MEMBERS(3, a, b, c)
  else RKPM_MEMBERS(4, a, b, c, d)
  else RKPM_MEMBERS(5, a, b, c, d, e)
  else RKPM_MEMBERS(6, a, b, c, d, e, f)
  else RKPM_MEMBERS(7, a, b, c, d, e, f, g)
  else RKPM_MEMBERS(8, a, b, c, d, e, f, g, h)
  else return members<void>{};  // more than 8 members: not recognised
#undef RKPM_MEMBERS
}

template <class... M>
constexpr bool bitwise_members(members<M...>) {
  if constexpr ((std::is_void_v<M> || ...)) return false;
  else return (bitwise_leaf<std::remove_cvref_t<M>>() && ...);
}

// Every member of an aggregate is a bitwise leaf.
template <class T>
constexpr bool bitwise_aggregate() {
  if constexpr (!std::is_aggregate_v<T> || !std::is_trivially_destructible_v<T>)
    return false;
  else if constexpr (member_count<T>() == 0 || member_count<T>() > 8)
    return false;
  else
    return bitwise_members(decltype(member_types(std::declval<const T&>())){});
}

}  // namespace detail

template <class T>
concept bitwise_value = detail::bitwise_leaf<T>() || detail::bitwise_aggregate<T>();

}  // namespace rkpm
