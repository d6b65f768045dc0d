// SPDX-License-Identifier: Apache-2.0
// The strict JSON parser (auxiliary/json_strict.hpp): a repeated key is refused with its path,
// at any depth and inside arrays; the same key in different objects is fine; nesting past the
// limit is refused; syntax errors stay nlohmann's.
#include "auxiliary/json_strict.hpp"

#include <gtest/gtest.h>

#include <string>

namespace gazelod::aux {
namespace {

std::string error_of(const std::string& text, int depth = kDefaultMaxJsonDepth) {
  try {
    (void)parse_json_strict(text, depth);
  } catch (const JsonStrictError& e) {
    return e.what();
  }
  return "";
}

TEST(JsonStrict, RepeatedKeyIsRefusedWithItsPath) {
  EXPECT_EQ(error_of(R"({"a": 1, "b": 2, "a": 3})"),
            "a: the key appears twice in one object (which one counts is undefined)");
  EXPECT_EQ(error_of(R"({"scene": {"objects": [{"name": "x"}, {"name": "y", "lods": [], "name": "z"}]}})"),
            "scene.objects[1].name: the key appears twice in one object (which one counts is undefined)");
  EXPECT_EQ(error_of(R"([1, [2, 3], {"k": {"q": 1, "q": 2}}])"),
            "[2].k.q: the key appears twice in one object (which one counts is undefined)");
  EXPECT_EQ(error_of(R"({"": 1, "": 2})"), ": the key appears twice in one object (which one counts is undefined)")
      << "the empty key too";
}

TEST(JsonStrict, SameKeyInDifferentObjectsAndValuesAreKept) {
  const nlohmann::json j = parse_json_strict(R"({"a": {"x": 1}, "b": {"x": 2}, "c": [{"x": 3}, {"x": 4}], "x": 5})");
  EXPECT_EQ(j.at("c")[1].at("x").get<int>(), 4);
  EXPECT_EQ(j.at("x").get<int>(), 5);
  EXPECT_EQ(j.dump(),
            nlohmann::json::parse(R"({"a": {"x": 1}, "b": {"x": 2}, "c": [{"x": 3}, {"x": 4}], "x": 5})").dump());
  EXPECT_EQ(parse_json_strict("3").get<int>(), 3);
  EXPECT_EQ(parse_json_strict("[]").size(), 0u);
}

TEST(JsonStrict, NestingPastTheLimitIsRefused) {
  EXPECT_EQ(error_of(std::string(3, '[') + std::string(3, ']'), 3), "");
  EXPECT_EQ(error_of(std::string(4, '[') + std::string(4, ']'), 3),
            ": JSON nesting must be at most 3 levels of arrays and objects, got more");
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_NE(error_of(deep).find("at most 64 levels"), std::string::npos) << "refused before it costs stack";
}

TEST(JsonStrict, SyntaxErrorsStayNlohmannsWithTheirByte) {
  try {
    (void)parse_json_strict(R"({"a": 1,})");
    ADD_FAILURE() << "accepted a trailing comma";
  } catch (const nlohmann::json::parse_error& e) {
    EXPECT_EQ(e.byte, 9u);
  }
}

}  // namespace
}  // namespace gazelod::aux
