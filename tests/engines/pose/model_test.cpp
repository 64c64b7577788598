// The pose model's loading: a missing, truncated or altered model and a graph with an unknown
// op each fail with a message naming the file (or op) and saying how to get the model. None of
// these needs the real model.
#include <gtest/gtest.h>

#include <string>

#include "armmimic/core/sha256.h"
#include "armmimic/engines/pose.h"
#include "test_util.h"

namespace armmimic {
namespace {

using test::TempDir;
using test::WriteFile;

const char* kAdvice =
    "; install the package armmimic-models, or fetch the model with scripts/deps.sh --with-model "
    "in armmimic's source tree, or name the folder holding it";

TEST(PoseModelTest, AMissingModelNamesTheFileAndHowToGetIt) {
  TempDir dir;
  Status st;
  EXPECT_EQ(PoseNetwork::Load(dir.path(), &st), nullptr);
  EXPECT_EQ(st.key(), "analysis.model");
  EXPECT_EQ(st.message(), dir.path() + "/movenet-lightning.json not found" + kAdvice);
  WriteFile(dir.file("movenet-lightning.json"), std::string(161813, ' '));
  EXPECT_EQ(PoseNetwork::Load(dir.path(), &st), nullptr);
  EXPECT_EQ(st.message(), dir.file("movenet-lightning.bin") + " not found" + kAdvice);
}

// The weights file at its pinned size (so that the check reaches the JSON file's content).
void WriteWeightsOfPinnedSize(const TempDir& dir) {
  WriteFile(dir.file("movenet-lightning.bin"), std::string(4650216, '\0'));
}

TEST(PoseModelTest, ATruncatedModelFileIsNamedWithItsSize) {
  TempDir dir;
  WriteFile(dir.file("movenet-lightning.json"), std::string(1000, '{'));
  WriteWeightsOfPinnedSize(dir);
  Status st;
  EXPECT_EQ(PoseNetwork::Load(dir.path(), &st), nullptr);
  EXPECT_EQ(st.message(), dir.file("movenet-lightning.json") +
                              " is truncated (1000 bytes, the pinned model has 161813)" + kAdvice);
}

TEST(PoseModelTest, AnAlteredModelFailsItsChecksum) {
  TempDir dir;
  WriteFile(dir.file("movenet-lightning.json"), std::string(161813, ' '));
  WriteWeightsOfPinnedSize(dir);
  const std::string hex =
      Sha256Hex(reinterpret_cast<const std::uint8_t*>(std::string(161813, ' ').data()), 161813);
  Status st;
  EXPECT_EQ(PoseNetwork::Load(dir.path(), &st), nullptr);
  EXPECT_EQ(st.message(), dir.file("movenet-lightning.json") +
                              " does not match the pinned model (SHA-256 " + hex +
                              ", expected "
                              "df8cbde44d00f533ccc4916a7c6ebc17316532fb3fadad114ec667fef22872e9)" +
                              kAdvice);
}

// A MoveNet-shaped graph (four head scopes) whose centre head uses an op the builder lacks.
std::string GraphWithOp(const std::string& op) {
  auto node = [](const std::string& name, const std::string& node_op, const std::string& input) {
    return "{\"name\": \"" + name + "\", \"op\": \"" + node_op + "\"" +
           (input.empty() ? "" : ", \"input\": [\"" + input + "\"]") + "}";
  };
  return "{\"format\": \"graph-model\", \"modelTopology\": {\"node\": [" +
         node("input", "Placeholder", "") + ", " + node("kpt_heatmap_0/s", "Sigmoid", "input") +
         ", " + node("center_0/e", op, "input") + ", " +
         node("kpt_regress_0/s", "Sigmoid", "input") + ", " +
         node("kpt_offset_0/s", "Sigmoid", "input") +
         "]}, \"weightsManifest\": [{\"paths\": [\"w.bin\"], \"weights\": []}]}";
}

TEST(PoseModelTest, AnUnknownOpIsNamedWithItsNode) {
  TempDir dir;
  WriteFile(dir.file("model.json"), GraphWithOp("Erf"));
  WriteFile(dir.file("w.bin"), "");
  Status st;
  EXPECT_EQ(PoseNetwork::LoadUnchecked(dir.file("model.json"), &st), nullptr);
  EXPECT_EQ(st.message(), dir.file("model.json") + ": unknown op 'Erf' (node center_0/e)");
}

TEST(PoseModelTest, AShortWeightShardIsNamed) {
  TempDir dir;
  WriteFile(dir.file("model.json"),
            "{\"modelTopology\": {\"node\": [{\"name\": \"input\", \"op\": \"Placeholder\"}]}, "
            "\"weightsManifest\": [{\"paths\": [\"w.bin\"], \"weights\": [{\"name\": \"k\", "
            "\"shape\": [4], \"dtype\": \"float32\"}]}]}");
  WriteFile(dir.file("w.bin"), std::string(8, '\0'));
  Status st;
  EXPECT_EQ(PoseNetwork::LoadUnchecked(dir.file("model.json"), &st), nullptr);
  EXPECT_EQ(st.message(),
            dir.file("w.bin") + " is truncated: 8 bytes, but weight k needs bytes up to 16");
}

}  // namespace
}  // namespace armmimic
