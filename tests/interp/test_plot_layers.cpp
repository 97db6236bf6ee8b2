// plot{}: every layer and every colour quantity drawn from a model that has them all (a prepass,
// yielded zones, broken cracks, bolts, an excavation), each picture read back: the size asked
// for, more ink than the picture's frame alone, and no two layers alike.
#include <lua.hpp>

#include "../unit/picture_files.hpp"
#include "interp_test.hpp"
#include "model/model_plot.hpp"

namespace edem::test {
namespace {

const char* kTunnel = R"(
  local cavern = require "edem.cavern"
  local rockbolts = require "edem.bolts"
  local t = cavern.horseshoe{ width = 10, stages = 2 }
  model{ title = "every layer" }
  block{ x = {-40, 40}, y = {-40, 40} }
  jset{ angle = 60, spacing = 12, origin = {3, 0} }
  for _, s in ipairs(t.stages) do region(s) end
  crackseed{ angles = {120, 30}, spacing = 2, region = {{-15, -15}, {15, -15}, {15, 15}, {-15, 15}}, material = "intact" }
  zone{ edge = 1, far = 6, near = { t.outline } }
  material{ "rock", model = "mohr", density = 2600, young = 5e9, poisson = 0.25, cohesion = 0.4e6, friction = 35,
            tension = 0.1e6 }
  material{ "intact", model = "mohr", density = 2600, young = 5e9, poisson = 0.25, cohesion = 0.3e6, friction = 35,
            tension = 0.1e6 }
  assign{ material = "rock" }
  joint_material{ "j", kn = 5e10, ks = 5e9, friction = 30 }
  jassign{ material = "j" }
  gravity{ 0, -9.81 }
  insitu{ surface = 60, density = 2600, k0 = 0.8 }
  boundary{ side = "left", fix = "x" } boundary{ side = "right", fix = "x" }
  boundary{ side = "bottom", fix = "y" } boundary{ side = "top", stress = "insitu" }
  local names = {}
  for _, s in ipairs(t.stages) do names[#names + 1] = s.name end
  prepass{ stages = names, steps = 1 }
  bolt_material{ "rebar", young = 200e9, area = 4.9e-4, yield_tension = 0.156e6, failure_strain = 0.035,
                 bond_stiffness = 50e6, bond_strength = 0.2e6, spacing = 1.5 }
  for _, s in ipairs(t.stages) do
    excavate{ region = s.name, release = 300 }
    solve{ ratio = 1e-5, max_cycles = 3000 }
    rockbolts.pattern{ surface = rockbolts.exposed(s, t.outline), spacing = 1.5, length = 4, segments = 8,
                       material = "rebar" }
  end
  cycle(50)
  local yielded = 0
  for z in zones() do if z.state ~= "elastic" then yielded = yielded + 1 end end
  assert(yielded > 0 and info().cracks > 0, "the scene must have yielded zones and cracks")
)";

class PlotLayers : public PictureDir {};

TEST_F(PlotLayers, EveryLayerAndColourDrawsSomethingOfItsOwn) {
  Interpreter interpreter({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  std::string script = kTunnel;
  std::vector<std::pair<std::string, std::string>> pictures;  // name, plot{} arguments
  for (const std::string& layer : plot_layers())
    pictures.push_back({layer, "show = {\"" + layer + "\"}"});
  for (const std::string& quantity : plot_colours())
    pictures.push_back({"colour_" + quantity, "show = {\"blocks\"}, colour = \"" + quantity + "\""});
  for (const auto& [name, arguments] : pictures)
    script += "plot{ file = '" + file(name + ".png") + "', size = {640, 480}, window = {-20, 20, -15, 20}, " +
              arguments + " }\n";
  // The frame alone (title, scale bar, counts): the blocks layer with the window off the model.
  script += "plot{ file = '" + file("frame.png") + "', size = {640, 480}, window = {1000, 1040, 1000, 1035}, "
            "show = {'blocks'} }\n";
  expect_runs(interpreter, script);
  const Picture frame = read_png(file("frame.png"));
  ASSERT_EQ(frame.width, 640);
  std::vector<std::pair<std::string, Picture>> read;
  for (const auto& [name, arguments] : pictures) {
    SCOPED_TRACE(name);
    Picture picture = read_png(file(name + ".png"));
    EXPECT_EQ(picture.width, 640);
    EXPECT_EQ(picture.height, 480);
    // At least half a percent of the picture inked beyond what the frame alone inks.
    EXPECT_GT(picture.inked(), frame.inked() + 0.005) << "blank: " << picture.inked() << " inked, the frame alone "
                                                      << frame.inked();
    for (const auto& [other, seen] : read) EXPECT_NE(picture.pixels, seen.pixels) << "the same as " << other;
    read.push_back({name, std::move(picture)});
  }
}

TEST_F(PlotLayers, UnknownColourIsAnErrorWithAHint) {
  Interpreter interpreter({.quiet = true, .threads = 1, .stdlib_dirs = {}});
  const std::string error = error_of(interpreter, "block{ x = {0, 1}, y = {0, 1} }\nzone{ edge = 0.5 }\n"
                                                  "plot{ file = '" + file("x.png") + "', colour = 'sy' }");
  EXPECT_TRUE(contains(error, "test.lua:3: plot: colour must be one of"));
}

}  // namespace
}  // namespace edem::test
