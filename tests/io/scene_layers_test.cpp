// A scene's layers that no method uses (a background, a title): the reader keeps each
// top-level group as written, the scene loader picks those that are not Pak's and places
// them under the container or over the elements, and the writer copies them as they are with
// the definitions they need, every id once.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

#include "io/svg_builder.hpp"
#include "pak/io/packing_drawing.hpp"
#include "pak/io/scene_loader.hpp"
#include "pak/io/svg_writer.hpp"

namespace pak {
namespace {

const std::string kBackground =
    R"~(<g inkscape:groupmode="layer" id="layer1" inkscape:label="Background"><rect id="paper" width="100" height="100" fill="url(#paperFill)"/><use xlink:href="#disc" opacity="0.3"/></g>)~";
const std::string kTitle =
    R"~(<g id="Title"><text x="50" y="8" fill="#333">Leaves &amp; co</text><rect id="rule" x="10" y="10" width="80" height="1" style="fill:url(#ink)"/></g>)~";
const std::string kHidden = R"~(<g id="notes" style="display:none"><rect width="5" height="5"/></g>)~";
const std::string kPaperFill =
    R"~(<linearGradient id="paperFill" xlink:href="#paperStops"/>)~";
const std::string kPaperStops =
    R"~(<linearGradient id="paperStops"><stop offset="0" stop-color="#fff"/><stop offset="1" stop-color="#eee"/></linearGradient>)~";
const std::string kInk = R"~(<linearGradient id="ink"><stop offset="0" stop-color="#000"/></linearGradient>)~";

std::string scene(const std::string& extra = "") {
  return R"~(<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink"
  xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape" width="100mm" height="100mm" viewBox="0 0 100 100">
  <defs>)~" + kPaperStops + kPaperFill + kInk + R"~(<linearGradient id="unused"/></defs>
  )~" + kBackground + R"~(
  <g id="container"><circle id="disc" cx="50" cy="50" r="40" fill="url(#ink)"/></g>
  <g id="fixed"><rect id="logo" x="45" y="45" width="10" height="10" fill="url(#ink)"/></g>
  )~" + kTitle + "\n  " + kHidden + R"~(
  <g id="guides"><path d="M20 50 H80" stroke="#00f"/></g>
  )~" + extra + "\n</svg>";
}

bool hasDefinition(const RawMarkup& markup, const std::string& text) {
  return std::find(markup.definitions.begin(), markup.definitions.end(), text) != markup.definitions.end();
}

TEST(SceneLayers, ReaderKeepsEveryTopLevelGroupAsWritten) {
  const SvgDocument document = readSvgString(scene(), "scene.svg");
  ASSERT_EQ(document.topGroups.size(), 6u);
  const SvgTopGroup& background = document.topGroups[0];
  EXPECT_EQ(background.name, "Background");
  EXPECT_EQ(background.layers, std::vector<std::string>{"background"});
  EXPECT_EQ(background.markup.content, kBackground);
  // What it references and does not hold: the gradient, the stops it borrows, the cloned disc
  // and the disc's gradient.
  EXPECT_EQ(background.markup.definitions.size(), 4u);
  for (const std::string& definition :
       {kPaperFill, kPaperStops, kInk, std::string(R"~(<circle id="disc" cx="50" cy="50" r="40" fill="url(#ink)"/>)~")})
    EXPECT_TRUE(hasDefinition(background.markup, definition)) << definition;
  // xlink: from the <use>, which the reader has expanded by now.
  EXPECT_NE(std::find(background.markup.namespaces.begin(), background.markup.namespaces.end(),
                      std::pair<std::string, std::string>{"xlink", "http://www.w3.org/1999/xlink"}),
            background.markup.namespaces.end());
  EXPECT_EQ(document.topGroups[1].layers, std::vector<std::string>{"container"});
  EXPECT_EQ(document.topGroups[3].name, "Title");
  EXPECT_EQ(document.topGroups[3].markup.content, kTitle);
  EXPECT_EQ(document.topGroups[3].markup.definitions, std::vector<std::string>{kInk});
  EXPECT_EQ(document.topGroups[4].markup.content, kHidden);  // hidden: copied, still hidden
  // The shapes say which group they are in; so do the warnings.
  for (const SvgShape& shape : document.shapes)
    if (shape.id == "rule") {
      EXPECT_EQ(shape.topGroup, 3);
    }
  const auto text = std::find_if(document.warnings.begin(), document.warnings.end(),
                                 [](const Warning& w) { return w.message.find("<text>") != std::string::npos; });
  ASSERT_NE(text, document.warnings.end());
  EXPECT_EQ(text->topGroup, 3);
}

// A prefix only a <use> names (the reader has replaced it by its copy by the time it copies the
// layer) is still declared for the copy, or the output would not be XML.
TEST(SceneLayers, APrefixOnlyAUseNamesIsDeclared) {
  const SvgDocument document = readSvgString(R"~(<svg xmlns="http://www.w3.org/2000/svg"
      xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 10 10"><defs><circle id="dot" r="1"/></defs>
      <g id="stamp"><use xlink:href="#dot" x="5" y="5"/></g></svg>)~", "stamp.svg");
  ASSERT_EQ(document.topGroups.size(), 1u);
  EXPECT_EQ(document.topGroups[0].markup.namespaces,
            (std::vector<std::pair<std::string, std::string>>{{"xlink", "http://www.w3.org/1999/xlink"}}));
}

// Inkscape's rgb() with decimals, which the reader rounds for itself, is no stylesheet: the
// layers are still copied as written.
TEST(SceneLayers, RoundedColoursAreNoStylesheet) {
  const SvgDocument document = readSvgString(R"~(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">
      <g id="fixed"><rect width="2" height="2" style="fill:rgb(12.5, 100.2, 200)"/></g>
      <g id="paper"><rect width="10" height="10" style="fill:rgb(250.4, 250.6, 240)"/></g></svg>)~", "inkscape.svg");
  EXPECT_NE(document.fixedMarkup.content.find("rgb(12.5, 100.2, 200)"), std::string::npos);
  ASSERT_EQ(document.topGroups.size(), 2u);
  EXPECT_FALSE(document.topGroups[1].styledBySheet);
  EXPECT_NE(document.topGroups[1].markup.content.find("rgb(250.4, 250.6, 240)"), std::string::npos);
}

TEST(SceneLayers, SceneCopiesTheLayersPakDoesNotUseInTheirPlaces) {
  const LoadedScene loaded = sceneFromDocument(readSvgString(scene(), "scene.svg"));
  const SceneLayout& layout = loaded.layout;
  ASSERT_EQ(layout.layersBelow.size(), 1u);
  EXPECT_EQ(layout.layersBelow[0].name, "Background");
  EXPECT_EQ(layout.layersBelow[0].markup.content, kBackground);
  ASSERT_EQ(layout.layersAbove.size(), 2u);  // fixed and guides are Pak's
  EXPECT_EQ(layout.layersAbove[0].name, "Title");
  EXPECT_EQ(layout.layersAbove[1].name, "notes");
  EXPECT_EQ(layout.layersAbove[0].shapes.size(), 1u);  // the rule: what the PNG preview draws
  EXPECT_TRUE(layout.layersAbove[1].shapes.empty());   // hidden
  // Copied, not read: no word of their text or gradients; the container's gradient still warns.
  for (const Warning& warning : loaded.warnings) {
    EXPECT_EQ(warning.message.find("<text>"), std::string::npos) << warning.message;
    EXPECT_EQ(warning.message.find("paperFill"), std::string::npos) << warning.message;
  }
  EXPECT_TRUE(std::any_of(loaded.warnings.begin(), loaded.warnings.end(),
                          [](const Warning& w) { return w.where.find("disc") != std::string::npos; }));
  EXPECT_EQ(layout.widthText, "100mm");
}

TEST(SceneLayers, AContainerLayerOfAnotherNameIsNotCopiedNorAnyOfPaksLayers) {
  SceneOptions options;
  options.containerLayer = "title";
  const LoadedScene loaded = sceneFromDocument(readSvgString(scene(), "scene.svg"), options);
  ASSERT_EQ(loaded.layout.layersBelow.size(), 1u);
  EXPECT_EQ(loaded.layout.layersBelow[0].name, "Background");
  ASSERT_EQ(loaded.layout.layersAbove.size(), 1u);
  EXPECT_EQ(loaded.layout.layersAbove[0].name, "notes");
}

// A file that is a container by itself has no other layers: every shape outlines it.
TEST(SceneLayers, AFileWithoutAContainerLayerCopiesNothing) {
  const LoadedScene loaded = sceneFromDocument(readSvgString(
      R"~(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><g id="art"><rect width="8" height="8"/></g></svg>)~",
      "icon.svg"));
  EXPECT_TRUE(loaded.layout.layersBelow.empty());
  EXPECT_TRUE(loaded.layout.layersAbove.empty());
}

TEST(SceneLayers, StyledLayersAreRedrawnAndMixedGroupsLeftOutWithAWarning) {
  const std::string text = R"~(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">
  <style>.paper{fill:#abc}</style>
  <g id="Paper"><rect class="paper" width="100" height="100"/></g>
  <g id="Layer 1"><g id="container"><rect x="10" y="10" width="80" height="80"/></g><circle r="3"/></g></svg>)~";
  const LoadedScene loaded = sceneFromDocument(readSvgString(text, "styled.svg"));
  ASSERT_EQ(loaded.layout.layersBelow.size(), 1u);
  const SceneLayer& paper = loaded.layout.layersBelow[0];
  EXPECT_TRUE(paper.markup.empty());  // a copy would lose the class's colour
  ASSERT_EQ(paper.shapes.size(), 1u);
  EXPECT_EQ(*paper.shapes[0].fill, (Color{0xaa, 0xbb, 0xcc, 1.0}));
  EXPECT_TRUE(loaded.layout.layersAbove.empty());
  auto warned = [&](const std::string& where, const std::string& what) {
    return std::any_of(loaded.warnings.begin(), loaded.warnings.end(), [&](const Warning& w) {
      return w.where.find(where) != std::string::npos && w.message.find(what) != std::string::npos;
    });
  };
  EXPECT_TRUE(warned("layer 'Paper'", "<style> sheet"));
  EXPECT_TRUE(warned("layer 'Layer 1'", "leaves the others out"));

  // Re-drawn as a layer of the same name, with the reader's shapes.
  const std::string svg = toSvgString(packingDrawing(loaded.layout, Packing{}));
  EXPECT_NE(svg.find(R"~(<g inkscape:groupmode="layer" inkscape:label="Paper">)~"), std::string::npos) << svg;
  EXPECT_NE(svg.find(R"~(fill="#aabbcc")~"), std::string::npos);
}

// Every id="…" of a document with how often it occurs.
std::map<std::string, int> idCounts(const std::string& svg) {
  std::map<std::string, int> counts;
  for (std::size_t at = svg.find(" id=\""); at != std::string::npos; at = svg.find(" id=\"", at + 1)) {
    const std::size_t begin = at + 5;
    ++counts[svg.substr(begin, svg.find('"', begin) - begin)];
  }
  return counts;
}

TEST(SceneLayers, OutputCopiesThemVerbatimAroundThePackingWithEveryIdOnce) {
  const LoadedScene loaded = sceneFromDocument(readSvgString(scene(), "scene.svg"));
  const std::string svg = toSvgString(packingDrawing(loaded.layout, Packing{}));
  EXPECT_NE(svg.find(R"~(width="100mm" height="100mm" viewBox="0 0 100 100")~"), std::string::npos);
  const std::size_t background = svg.find(kBackground), title = svg.find(kTitle), hidden = svg.find(kHidden);
  ASSERT_NE(background, std::string::npos) << svg;
  ASSERT_NE(title, std::string::npos) << svg;
  ASSERT_NE(hidden, std::string::npos) << svg;
  EXPECT_LT(background, svg.find("<g id=\"container\""));
  EXPECT_LT(svg.find("<g id=\"elements\""), title);
  EXPECT_LT(title, hidden);
  // ink is referenced by the fixed layer and the title: written once. The copied disc keeps
  // its id; Pak's container path, drawn from the same shape, gives way.
  for (const std::string& definition : {kPaperFill, kPaperStops, kInk}) {
    const std::size_t at = svg.find(definition);
    EXPECT_NE(at, std::string::npos) << definition;
    EXPECT_EQ(svg.find(definition, at + 1), std::string::npos) << definition;
  }
  EXPECT_EQ(svg.find("unused"), std::string::npos);
  EXPECT_NE(svg.find(R"~(<path id="disc-2")~"), std::string::npos) << svg;
  for (const auto& [id, count] : idCounts(svg)) EXPECT_EQ(count, 1) << id;
  EXPECT_NE(svg.find("xmlns:xlink=\"http://www.w3.org/1999/xlink\""), std::string::npos);
  readSvgString(svg, "out.svg");  // well-formed
}

TEST(SceneLayers, BuilderFindsTheIdsOfCopiedMarkup) {
  svg_builder::SvgBuilder builder(3, 0.0);
  Drawing drawing;
  drawing.viewBox = {{0, 0}, {10, 10}};
  DrawingGroup copied;
  copied.markup = RawMarkup{R"~(<g id = 'elements' data-id="x"><rect id="container"/></g>)~", {}, {}};
  copied.markupReplacesGroup = true;
  drawing.groups = {copied, {"container", "", {}, {}, {}}, {"elements", "", {}, {}, {}}};
  builder.beginDocument({&drawing});
  for (const DrawingGroup& group : drawing.groups) builder.writeGroup(group, 1);
  builder.endDocument();
  const std::string& svg = builder.text();
  EXPECT_NE(svg.find(R"~(<g id="container-2")~"), std::string::npos) << svg;
  EXPECT_NE(svg.find(R"~(<g id="elements-2")~"), std::string::npos) << svg;
  EXPECT_EQ(builder.uniqueId("x"), "x");  // data-id is another attribute
}

}  // namespace
}  // namespace pak
