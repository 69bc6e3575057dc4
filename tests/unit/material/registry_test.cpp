// The material registry: every violation path names the right key with the rule in words; valid
// input builds the right model; docs/materials.md is exactly what the registry generates.
#include "material/registry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "core/error.hpp"

namespace plisse {
namespace {

void expect_one(const std::vector<ParamViolation>& v, const std::string& key,
                const std::string& rule) {
  std::string all;
  for (const auto& x : v) all += x.key + ": " + x.rule + "; ";
  ASSERT_EQ(v.size(), 1u) << all;
  EXPECT_EQ(v[0].key, key);
  EXPECT_EQ(v[0].rule, rule);
}

TEST(MaterialRegistry, UnknownModelIsReportedAgainstTheModelKey) {
  expect_one(
      validate_material("rubber", {{"c1", 1.0}}), "model",
      "unknown material model 'rubber' (known: neo-hookean, mooney-rivlin, fung, yeoh, gent, "
      "arruda-boyce, ogden, fibre-reinforced)");
  EXPECT_EQ(find_material_model("rubber"), nullptr);
}

TEST(MaterialRegistry, UnknownParameterIsReportedAgainstItsKey) {
  expect_one(validate_material("neo-hookean", {{"c1", 1.0}, {"c2", 0.5}}), "c2",
             "unknown parameter for model 'neo-hookean' (parameters: c1)");
}

TEST(MaterialRegistry, MissingRequiredParameterIsReported) {
  expect_one(validate_material("fung", {{"mu", 1.0}}), "gamma",
             "required by model 'fung' but missing (-, > 0: exponential stiffening coefficient)");
}

TEST(MaterialRegistry, NonFiniteValuesAreRejected) {
  expect_one(validate_material("neo-hookean", {{"c1", std::numeric_limits<double>::quiet_NaN()}}),
             "c1", "must be a finite number (got nan)");
  expect_one(validate_material("neo-hookean", {{"c1", std::numeric_limits<double>::infinity()}}),
             "c1", "must be a finite number (got inf)");
}

TEST(MaterialRegistry, OutOfRangeValuesNameTheRule) {
  expect_one(validate_material("neo-hookean", {{"c1", -1.0}}), "c1", "must be > 0 (got -1)");
  expect_one(validate_material("mooney-rivlin", {{"c1", -1.0}, {"c2", 2.0}}), "c1",
             "must be >= 0 (got -1)");
  expect_one(validate_material("arruda-boyce", {{"mu", 1.0}, {"lambda_m", 1.0}}), "lambda_m",
             "must be > 1 (got 1)");
  expect_one(validate_material("yeoh", {{"c1", 1.0}, {"c3", -0.1}}), "c3",
             "must be >= 0 (got -0.1)");
  expect_one(validate_material("gent", {{"mu", 1.0}, {"jm", 0.0}}), "jm", "must be > 0 (got 0)");
}

TEST(MaterialRegistry, CrossRulesQuoteTheValuesInvolved) {
  expect_one(validate_material("mooney-rivlin", {{"c1", 0.0}, {"c2", 0.0}}), "c1",
             "c1 + c2 must be > 0 (got c1 = 0, c2 = 0)");
  // c2 < 0 (fitted sets often have it) is accepted while the shear modulus is positive; a run
  // reports where it is stable (RunRecorder::material_stable_range).
  EXPECT_TRUE(validate_material("mooney-rivlin", {{"c1", 1.0}, {"c2", -0.2}}).empty());
  expect_one(validate_material("mooney-rivlin", {{"c1", 1.0}, {"c2", -2.0}}), "c1",
             "c1 + c2 must be > 0 (got c1 = 1, c2 = -2)");
  expect_one(validate_material("yeoh", {{"c1", 1.0}, {"c2", -2.0}, {"c3", 0.1}}), "c2",
             "c2 must be >= 0 or c2^2 < 3 c1 c3 (dW/dĪ1 > 0 for all Ī1 >= 3) (got c1 = 1, c2 = -2, "
             "c3 = 0.1)");
  EXPECT_TRUE(
      validate_material("yeoh", {{"c1", 1.0}, {"c2", -0.5}, {"c3", 0.1}}).empty());  // 0.25 < 0.3
}

TEST(MaterialRegistry, SeveralProblemsAreAllReportedAndCrossRulesWaitForValidValues) {
  const auto v = validate_material("mooney-rivlin", {{"c1", -1.0}, {"k", 2.0}});
  ASSERT_EQ(v.size(), 3u);  // unknown k, c1 out of range, c2 missing; no cross rule on bad values
  EXPECT_EQ(v[0].key, "k");
  EXPECT_EQ(v[1].key, "c1");
  EXPECT_EQ(v[2].key, "c2");
}

TEST(MaterialRegistry, ValidInputBuildsTheModelWithDefaults) {
  ASSERT_TRUE(validate_material("yeoh", {{"c1", 0.4}}).empty());
  const AnyMaterial m = make_material("yeoh", {{"c1", 0.4}});
  ASSERT_TRUE(std::holds_alternative<Yeoh>(m));
  EXPECT_EQ(std::get<Yeoh>(m).c1, 0.4);
  EXPECT_EQ(std::get<Yeoh>(m).c2, 0.0);
  EXPECT_EQ(std::get<Yeoh>(m).c3, 0.0);
  const AnyMaterial mr = make_material("mooney-rivlin", {{"c1", 0.003}, {"c2", 0.001}});
  EXPECT_EQ(std::get<MooneyRivlin>(mr).c2, 0.001);
  EXPECT_DOUBLE_EQ(shear_modulus(mr), 0.008);
  EXPECT_EQ(material_name(mr), "mooney-rivlin");
}

TEST(MaterialRegistry, InvalidInputDoesNotBuild) {
  EXPECT_THROW(make_material("neo-hookean", {{"c1", -1.0}}), Error);
  EXPECT_THROW(make_material("rubber", {}), Error);
}

// Each model's documented shear modulus formula agrees with the code's, for the paper's values.
TEST(MaterialRegistry, ShearModulusOfEveryModel) {
  EXPECT_DOUBLE_EQ(shear_modulus(make_material("neo-hookean", {{"c1", 0.0033}})), 0.0066);
  EXPECT_DOUBLE_EQ(shear_modulus(make_material("fung", {{"mu", 0.0066}, {"gamma", 0.5}})), 0.0066);
  EXPECT_DOUBLE_EQ(shear_modulus(make_material("yeoh", {{"c1", 0.5}, {"c2", 1.0}})), 1.0);
  EXPECT_DOUBLE_EQ(shear_modulus(make_material("gent", {{"mu", 0.7}, {"jm", 50.0}})), 0.7);
  const double lm = 2.0, l2 = lm * lm;
  EXPECT_NEAR(shear_modulus(make_material("arruda-boyce", {{"mu", 1.0}, {"lambda_m", lm}})),
              1 + 3 / (5 * l2) + 99 / (175 * l2 * l2) + 513 / (875 * l2 * l2 * l2) +
                  42039 / (67375 * l2 * l2 * l2 * l2),
              1e-15);
}

TEST(MaterialRegistry, EveryAlternativeIsRegisteredOnceWithMatchingName) {
  std::set<std::string> names;
  std::set<std::size_t> indices;
  for (const auto& m : material_models()) {
    EXPECT_TRUE(names.insert(m.name).second) << m.name;
    EXPECT_TRUE(indices.insert(m.variant_index).second) << m.name;
    EXPECT_EQ(find_material_model(m.name), &m);
    EXPECT_FALSE(m.params.empty());
    for (const auto& p : m.params)
      EXPECT_FALSE(p.unit.empty() || p.help.empty()) << m.name << '.' << p.name;
  }
  EXPECT_EQ(indices.size(), std::variant_size_v<AnyMaterial>);
}

TEST(MaterialRegistry, CommittedManualEqualsGeneratedText) {
  const std::string path = std::string(PLISSE_SOURCE_DIR) + "/docs/materials.md";
  std::ifstream in(path);
  ASSERT_TRUE(in) << "cannot read " << path;
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), materials_markdown())
      << "docs/materials.md is out of date: regenerate it with `plisse materials --markdown > "
         "docs/materials.md`";
}

}  // namespace
}  // namespace plisse
