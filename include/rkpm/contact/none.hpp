#pragma once
// contact::none: no tools, no body pairs, no contact; satisfies Contact so that a run without
// contact uses the same solver (docs/method.md section 6).

#include <string_view>
#include <vector>

#include <rkpm/concepts/contact.hpp>
#include <rkpm/contact/contact_pair.hpp>
#include <rkpm/contact/rigid_tool.hpp>
#include <rkpm/io/checkpoint.hpp>

namespace rkpm::contact {

struct none {
  static constexpr std::string_view name = "none";
  void setup(const contact_body&, const contact_slaves&) {}
  void rebind(const contact_body&, const contact_slaves&) {}
  contact_result enforce(const contact_body&, double, double, std::vector<vec2>&, std::vector<vec2>&) { return {}; }
  const std::vector<rigid_tool>& tools() const { return tools_; }
  const std::vector<vec2>& reactions() const { return reactions_; }
  const std::vector<body_pair>& body_pairs() const { return body_pairs_; }
  void save(io::checkpoint_writer&) const {}  // no state
  void load(io::checkpoint_reader&) {}

 private:
  std::vector<rigid_tool> tools_;
  std::vector<vec2> reactions_;
  std::vector<body_pair> body_pairs_;
};

}  // namespace rkpm::contact
