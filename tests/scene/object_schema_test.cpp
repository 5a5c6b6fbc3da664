// A scene object's fields in JSON (scene/object_schema.h): each bad value is refused naming the
// object and the field, and what is written reads back as the same object.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/object_schema.h"

using namespace weft;
using nlohmann::json;

namespace {

std::vector<SectionTexture> two_textures() {
  std::vector<SectionTexture> out;
  for (int k = 0; k < 2; ++k) {
    auto image = std::make_shared<TextureImage>();
    image->width = 2 + k;
    image->height = 2;
    image->rgba.assign(size_t(image->width * image->height * 4), std::uint8_t(40 * (k + 1)));
    out.push_back({image, k == 0 ? "plaid.png" : "bumps.png"});
  }
  return out;
}

json drape() {
  return {{"name", "drape"},
          {"material", "cloth"},
          {"fabric", "polyester_voile"},
          {"optical_thickness", 0.7},
          {"weave_repeats_per_uv", {30.0, 12.0}},
          {"colour", {0.25, 0.5, 0.75}},
          {"display_name", "Voile"},
          {"composition", "100 % polyester"},
          {"thread_maps",
           {{{"texture", 0}, {"offset", {0.1, 0.2}}, {"scale", {4.0, 4.0}}, {"rotation", 0.5}}, nullptr}},
          {"normal_map",
           {{"texture", 1}, {"offset", {0.0, 0.0}}, {"scale", {2.0, 3.0}}, {"rotation", 0.0}, {"normal_scale", 0.6},
            {"colour_space", "linear"}}}};
}

json floor_object() { return {{"name", "floor"}, {"material", "lambertian"}, {"albedo", {0.5, 0.4, 0.3}}}; }

// What reading `object` as objects[1] throws, "" when it reads.
std::string refusal(const json& object) {
  try {
    read_scene_object(object, "room.json: objects[1]", two_textures());
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(SceneObjectSchema, ReadsEveryFieldOfAClothAndALambertianObject) {
  const std::vector<SectionTexture> textures = two_textures();
  const SceneObject o = read_scene_object(drape(), "objects[0]", textures);
  EXPECT_EQ(o.name, "drape");
  EXPECT_EQ(o.material, Material::cloth);
  EXPECT_EQ(o.fabric, "polyester_voile");
  EXPECT_EQ(o.optical_thickness, 0.7);
  EXPECT_EQ(o.weave_repeats_per_uv, glm::dvec2(30.0, 12.0));
  EXPECT_EQ(o.colour, glm::dvec3(0.25, 0.5, 0.75));
  EXPECT_EQ(o.display_name, "Voile");
  EXPECT_EQ(o.composition, "100 % polyester");
  ASSERT_TRUE(o.thread_maps[0]);
  EXPECT_FALSE(o.thread_maps[1]);
  EXPECT_EQ(o.thread_maps[0]->image, textures[0].image);
  EXPECT_EQ(o.thread_maps[0]->name, "plaid.png");
  EXPECT_EQ(o.thread_maps[0]->transform, (TextureTransform{{0.1, 0.2}, {4.0, 4.0}, 0.5}));
  ASSERT_TRUE(o.normal_map);
  EXPECT_EQ(o.normal_map->map.image, textures[1].image);
  EXPECT_EQ(o.normal_map->scale, 0.6);

  const SceneObject f = read_scene_object(floor_object(), "objects[1]", textures);
  EXPECT_EQ(f.material, Material::lambertian);
  EXPECT_EQ(f.albedo, glm::dvec3(0.5, 0.4, 0.3));
}

TEST(SceneObjectSchema, AbsentOptionalFieldsTakeTheirDefaults) {
  const json plain = {{"name", "pillow"}, {"material", "cloth"}, {"fabric", "linen_plain"}};
  const SceneObject o = read_scene_object(plain, "objects[0]", {});
  EXPECT_EQ(o.optical_thickness, 0.0);
  EXPECT_EQ(o.weave_repeats_per_uv, glm::dvec2(0.0));
  EXPECT_FALSE(o.colour);
  EXPECT_EQ(o.display_name, "");
  EXPECT_FALSE(o.textured());
  EXPECT_FALSE(o.normal_map);
  // The single-field readers a scene file and glTF extras use agree.
  EXPECT_EQ(read_optical_thickness(plain, "x"), 0.0);
  EXPECT_EQ(read_weave_repeats_per_uv(plain, "x"), glm::dvec2(0.0));
  EXPECT_FALSE(read_colour(plain, "x"));
  EXPECT_EQ(read_label_text(plain, "composition", "x"), "");
  EXPECT_EQ(read_texture_transform(json::object(), "x"), TextureTransform{});
}

TEST(SceneObjectSchema, EachBadValueIsRefusedNamingTheObjectAndTheField) {
  ASSERT_EQ(refusal(drape()), "");
  const std::string object = "room.json: objects[1] ('drape')";
  struct Case {
    std::string field;  // as the message names it, after the object
    json value;         // null: remove the field
  };
  const std::vector<Case> cases = {
      {"material", "metal"},
      {"material", 3},
      {"fabric", ""},
      {"fabric", 5},
      {"fabric", nullptr},
      {"optical_thickness", 0.0},
      {"optical_thickness", -1.0},
      {"optical_thickness", 25.0},
      {"optical_thickness", "thick"},
      {"weave_repeats_per_uv", {0.0, 1.0}},
      {"weave_repeats_per_uv", {1.0}},
      {"weave_repeats_per_uv", {2e6, 1.0}},
      {"weave_repeats_per_uv", "dense"},
      {"colour", {0.5, 1.5, 0.2}},
      {"colour", {0.1, 0.2}},
      {"colour", "red"},
      {"display_name", 5},
      {"display_name", "two\nlines"},
      {"composition", std::string(121, 'x')},
      {"thread_maps", {nullptr}},
      {"thread_maps", "plaid"},
  };
  for (const Case& c : cases) {
    json j = drape();
    if (c.value.is_null())
      j.erase(c.field);
    else
      j[c.field] = c.value;
    const std::string why = refusal(j);
    const std::string named = c.value.is_null() ? object + ": missing field '" + c.field + "'" : object + "." + c.field;
    EXPECT_NE(why.find(named), std::string::npos) << c.field << " " << c.value.dump() << ": " << why;
  }
  // A map's texture and transform, and a normal map's scale.
  const auto map_refusal = [&](const char* map, const char* key, const json& value, const std::string& field) {
    json j = drape();
    json& m = std::string(map) == "thread_maps" ? j[map][0] : j[map];
    if (value.is_null())
      m.erase(key);
    else
      m[key] = value;
    const std::string why = refusal(j);
    EXPECT_NE(why.find(object + "." + field), std::string::npos) << map << "." << key << " " << value.dump() << ": " << why;
  };
  map_refusal("thread_maps", "texture", 2, "thread_maps[0].texture");
  map_refusal("thread_maps", "texture", -1, "thread_maps[0].texture");
  map_refusal("thread_maps", "texture", nullptr, "thread_maps[0]: missing field 'texture'");
  map_refusal("thread_maps", "offset", {1.0}, "thread_maps[0].offset");
  map_refusal("thread_maps", "scale", {0.0, 1.0}, "thread_maps[0]: a scale of 0");
  map_refusal("thread_maps", "rotation", "right", "thread_maps[0].rotation");
  map_refusal("normal_map", "normal_scale", 1e9, "normal_map.normal_scale");
  map_refusal("normal_map", "normal_scale", "strong", "normal_map.normal_scale");
  map_refusal("normal_map", "normal_scale", nullptr, "normal_map: missing field 'normal_scale'");
  map_refusal("normal_map", "texture", 7, "normal_map.texture");

  // A Lambertian's albedo; a name that is not a string names the object by its place.
  for (const json& bad : {json{0.5, -0.1, 0.2}, json{1.0, 2.0}, json("grey")}) {
    json f = floor_object();
    f["albedo"] = bad;
    const std::string why = refusal(f);
    EXPECT_NE(why.find("room.json: objects[1] ('floor').albedo"), std::string::npos) << bad.dump() << ": " << why;
  }
  json unnamed = drape();
  unnamed["name"] = 4;
  EXPECT_NE(refusal(unnamed).find("room.json: objects[1].name: expected a string"), std::string::npos) << refusal(unnamed);
  EXPECT_NE(refusal(json::array()).find("room.json: objects[1]: expected an object"), std::string::npos);
}

TEST(SceneObjectSchema, OneMessagePerBadValueNamesTheValue) {
  json j = drape();
  j["optical_thickness"] = 25;
  EXPECT_EQ(refusal(j), "room.json: objects[1] ('drape').optical_thickness: expected a number in (0, 20], got 25");
  j = drape();
  j["material"] = "metal";
  EXPECT_EQ(refusal(j), "room.json: objects[1] ('drape').material: 'metal' is neither 'cloth' nor 'lambertian'");
}

TEST(SceneObjectSchema, WhatIsWrittenReadsBackAsTheSameObject) {
  const std::vector<SectionTexture> textures = two_textures();
  const auto index_of = [&](const ThreadMap& m) -> size_t {
    for (size_t k = 0; k < textures.size(); ++k)
      if (textures[k].image == m.image) return k;
    ADD_FAILURE() << "an image not among the textures";
    return 0;
  };
  SceneObject in = read_scene_object(drape(), "objects[0]", textures);
  in.thread_maps[1] = ThreadMap{textures[1].image, textures[1].name, TextureTransform{{0.5, 0.0}, {-1.0, 2.0}, 1.25}};
  const json written = write_scene_object(in, index_of);
  const SceneObject out = read_scene_object(json::parse(written.dump(2)), "objects[0]", textures);
  EXPECT_EQ(out.name, in.name);
  EXPECT_EQ(out.material, in.material);
  EXPECT_EQ(out.fabric, in.fabric);
  EXPECT_EQ(out.optical_thickness, in.optical_thickness);
  EXPECT_EQ(out.weave_repeats_per_uv, in.weave_repeats_per_uv);
  EXPECT_EQ(out.colour, in.colour);
  EXPECT_EQ(out.display_name, in.display_name);
  EXPECT_EQ(out.composition, in.composition);
  for (int t = 0; t < 2; ++t) {
    ASSERT_TRUE(out.thread_maps[t]) << t;
    EXPECT_EQ(out.thread_maps[t]->image, in.thread_maps[t]->image);
    EXPECT_EQ(out.thread_maps[t]->name, in.thread_maps[t]->name);
    EXPECT_EQ(out.thread_maps[t]->transform, in.thread_maps[t]->transform);
  }
  ASSERT_TRUE(out.normal_map);
  EXPECT_EQ(out.normal_map->map.image, in.normal_map->map.image);
  EXPECT_EQ(out.normal_map->map.transform, in.normal_map->map.transform);
  EXPECT_EQ(out.normal_map->scale, in.normal_map->scale);
  // The drape as given is what is written back: the same keys and values.
  SceneObject as_given = read_scene_object(drape(), "objects[0]", textures);
  EXPECT_EQ(write_scene_object(as_given, index_of), drape());

  const SceneObject floor = read_scene_object(floor_object(), "objects[1]", textures);
  EXPECT_EQ(write_scene_object(floor, index_of), floor_object());
  const SceneObject back = read_scene_object(write_scene_object(floor, index_of), "objects[1]", textures);
  EXPECT_EQ(back.material, Material::lambertian);
  EXPECT_EQ(back.albedo, floor.albedo);
}

TEST(SceneObjectSchema, FieldsAtTheirAbsentValueAreLeftOut) {
  SceneObject o;
  o.name = "pillow";
  o.material = Material::cloth;
  o.fabric = "linen_plain";
  const json j = write_scene_object(o, [](const ThreadMap&) -> size_t { return 0; });
  EXPECT_EQ(j, (json{{"name", "pillow"}, {"material", "cloth"}, {"fabric", "linen_plain"}}));
  EXPECT_STREQ(material_name(Material::cloth), "cloth");
  EXPECT_STREQ(material_name(Material::lambertian), "lambertian");
}
