#pragma once
// For table-driven tests of config rules (a struct's FindConfigViolation): each case starts from
// a valid config, breaks one rule and names the key the violation must carry.

#include <functional>
#include <ostream>
#include <string>

#include <gtest/gtest.h>

namespace shelfdock::testing {

/// One rule of `Config`: how to break it and the key (dotted, as in the YAML file) it reports.
template <typename Config>
struct RuleCase {
  std::string name;  ///< test name
  std::string key;   ///< the key the violation must name
  std::function<void(Config&)> breaks;
};

template <typename Config>
std::ostream& operator<<(std::ostream& os, const RuleCase<Config>& c) {
  return os << c.name;
}

/// Checks that `config` passes, then that breaking `rule` in it is reported with exactly the
/// rule's key and a requirement. FindConfigViolation is found next to `Config`.
template <typename Config>
void ExpectRuleNamesItsKey(Config config, const RuleCase<Config>& rule) {
  ASSERT_FALSE(FindConfigViolation(config)) << "the starting config must pass";
  rule.breaks(config);
  const auto v = FindConfigViolation(config);
  ASSERT_TRUE(v.has_value()) << rule.name << ": no violation reported";
  EXPECT_EQ(v->key, rule.key) << v->requirement;
  EXPECT_FALSE(v->requirement.empty());
}

/// The test name of a parameterised rule test: the case's name.
inline constexpr auto kRuleName = [](const auto& info) { return info.param.name; };

}  // namespace shelfdock::testing
