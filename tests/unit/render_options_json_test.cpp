// app/render_options_json.h: a render's options round-trip through the JSON a checkpoint keeps, and a forged value
// (a float where a count belongs, a number past a float's range) is refused with one line instead of converted by
// undefined behaviour.
#include "app/render_options_json.h"

#include <gtest/gtest.h>

#include "error.h"

using namespace vkmc;

TEST(RenderOptionsJson, RoundTripsAndRefusesForgedNumbers) {
  RenderOptions o;
  o.scenePath = "/scenes/x.gltf";
  o.width = 64;
  o.spp = 128;
  o.lookFrom = glm::vec3(1, 2, 3), o.lookAt = glm::vec3(0.0f);
  const nlohmann::json j = renderOptionsJson(o);
  EXPECT_EQ(renderOptionsJson(renderOptionsFromJson(j)), j);
  for (const auto& [key, value] : {std::pair<const char*, nlohmann::json>{"spp", 1e300},
                                   {"spp", -1},
                                   {"width", 2.5},
                                   {"fov", 1e300},
                                   {"time_budget", "soon"},
                                   {"look_from", nlohmann::json::array({0, 1e300, 0})}}) {
    nlohmann::json forged = j;
    forged[key] = value;
    EXPECT_THROW(renderOptionsFromJson(forged), Error) << key << " = " << value;
  }
}

// The built-in studio is a name, not a path: a checkpoint keeps it as it is (an absolute path would be looked for
// as a file on resume).
TEST(RenderOptionsJson, TheStudioEnvironmentStaysANameAndAFileBecomesAbsolute) {
  RenderOptions o;
  o.scenePath = "/scenes/x.gltf";
  o.environmentPath = "studio";
  EXPECT_EQ(renderOptionsJson(o)["environment"], "studio");
  EXPECT_EQ(renderOptionsFromJson(renderOptionsJson(o)).environmentPath, "studio");
  o.environmentPath = "sky.hdr";
  EXPECT_EQ(renderOptionsJson(o)["environment"].get<std::string>().front(), '/');
}
