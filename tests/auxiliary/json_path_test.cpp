// SPDX-License-Identifier: Apache-2.0
// JSON paths and error lines (auxiliary/json_path.hpp), as the readers' messages spell them.
#include "auxiliary/json_path.hpp"

#include <gtest/gtest.h>

namespace gazelod::aux {
namespace {

TEST(JsonPath, Paths) {
  EXPECT_EQ(json_member_path("", "duration_s"), "duration_s");
  EXPECT_EQ(json_member_path("effects[2]", "amplitude_deg"), "effects[2].amplitude_deg");
  EXPECT_EQ(json_element_path("effects", 2), "effects[2]");
  EXPECT_EQ(json_element_path("", 0), "[0]");
  EXPECT_EQ(json_error_line("s.json", json_member_path(json_element_path("effects", 2), "type"), "unknown effect"),
            "s.json: effects[2].type: unknown effect");
}

TEST(JsonPath, TypeNamesAndUnknownKeys) {
  const auto j = nlohmann::json::parse(R"({"b": 1, "a": [true], "z": null, "c": "x"})");
  EXPECT_EQ(json_type_name(j), "object");
  EXPECT_EQ(json_type_name(j["a"]), "array");
  EXPECT_EQ(json_type_name(j["a"][0]), "boolean");
  EXPECT_EQ(json_type_name(j["z"]), "null");
  const std::string* unknown = first_unknown_key(j, {"a", "b"});
  ASSERT_NE(unknown, nullptr);
  EXPECT_EQ(*unknown, "c");  // the first in sorted order
  EXPECT_EQ(first_unknown_key(j, {"a", "b", "c", "z"}), nullptr);
  EXPECT_EQ(joined_keys({"a", "b", "c"}), "a, b, c");
}

}  // namespace
}  // namespace gazelod::aux
