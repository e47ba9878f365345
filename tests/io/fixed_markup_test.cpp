// The `fixed` layer travels to outputs as the artist wrote it: the reader keeps its source
// text (with the definitions and namespaces it needs), the writer copies it unchanged, and
// the copy reads back as the same shapes.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "pak/io/drawing.hpp"
#include "pak/io/svg_reader.hpp"
#include "pak/io/svg_writer.hpp"

namespace pak {
namespace {

// Inkscape-flavoured: labels, sodipodi attributes, style="…", a transform on the path, on the
// layer and on an unnamed ancestor, a gradient through an xlink:href chain, an entity.
const std::string kPath =
    R"~(<path style="fill:#1d3557;fill-opacity:1;stroke:#000000;stroke-width:1.5" d="m 100,100 c 20,0 40,20 40,40 0,20 -20,40 -40,40 z" id="path846" inkscape:label="Nose &amp; co" sodipodi:nodetypes="cscc" transform="rotate(10 120 140)" />)~";
const std::string kCircle = R"~(<circle cx="300" cy="150" r="30" fill="url(#eyeGradient)" id="eye"/>)~";
const std::string kRadial =
    R"~(<radialGradient id="eyeGradient" xlink:href="#stops" cx="300" cy="150" r="30" gradientUnits="userSpaceOnUse"/>)~";
const std::string kStops =
    R"~(<linearGradient inkscape:collect="always" id="stops"><stop offset="0" style="stop-color:#ff0000"/><stop offset="1" style="stop-color:#0000ff"/></linearGradient>)~";

std::string inkscapeScene() {
  return R"~(<?xml version="1.0" encoding="UTF-8" standalone="no"?>
<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink"
   xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"
   xmlns:sodipodi="http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd"
   width="1000" height="700" viewBox="0 0 1000 700">
  <sodipodi:namedview id="base" inkscape:zoom="1"/>
  <defs id="defs2">
    )~" + kStops + "\n    " + kRadial + R"~(
    <linearGradient id="unused"><stop offset="0" stop-color="#00ff00"/></linearGradient>
  </defs>
  <g inkscape:label="Container" inkscape:groupmode="layer" id="layer1">
    <rect x="50" y="50" width="900" height="600" fill="#eeeeff"/>
  </g>
  <g transform="translate(10,20)" opacity="0.5">
    <g inkscape:label="fixed" inkscape:groupmode="layer" id="layer2" style="display:inline" transform="scale(2)">
      )~" + kPath + "\n      <!-- the eye -->\n      " + kCircle + R"~(
    </g>
  </g>
</svg>
)~";
}

std::vector<SvgShape> fixedShapes(const SvgDocument& document) {
  std::vector<SvgShape> fixed;
  for (const SvgShape& shape : document.shapes)
    if (shape.layer == "fixed") fixed.push_back(shape);
  return fixed;
}

TEST(FixedMarkup, ReaderKeepsTheLayerSourceItsDefinitionsAndNamespaces) {
  SvgDocument document = readSvgString(inkscapeScene(), "scene.svg");
  const RawMarkup& markup = document.fixedMarkup;
  EXPECT_NE(markup.content.find(kPath), std::string::npos);
  EXPECT_NE(markup.content.find(kCircle), std::string::npos);
  EXPECT_NE(markup.content.find("<!-- the eye -->"), std::string::npos);
  // Placed by the ancestors' transform and opacity; the layer's own style kept, its id not.
  EXPECT_EQ(markup.content.rfind("<g transform=\"matrix(2 0 0 2 10 20)\" opacity=\"0.5\"><g style=\"display:inline\">", 0), 0u)
      << markup.content;
  EXPECT_EQ(markup.content.find("layer2"), std::string::npos);
  // The gradient the circle uses and the one holding its stops; not the unused one.
  EXPECT_EQ(markup.definitions.size(), 2u);
  for (const std::string& definition : {kRadial, kStops})
    EXPECT_NE(std::find(markup.definitions.begin(), markup.definitions.end(), definition), markup.definitions.end());
  using Ns = std::pair<std::string, std::string>;
  auto has = [&](const Ns& ns) { return std::find(markup.namespaces.begin(), markup.namespaces.end(), ns) != markup.namespaces.end(); };
  EXPECT_TRUE(has({"inkscape", "http://www.inkscape.org/namespaces/inkscape"}));
  EXPECT_TRUE(has({"sodipodi", "http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd"}));
  EXPECT_TRUE(has({"xlink", "http://www.w3.org/1999/xlink"}));
}

TEST(FixedMarkup, WriterCopiesItVerbatimAndItReadsBackAsTheSameShapes) {
  SvgDocument input = readSvgString(inkscapeScene(), "scene.svg");
  const std::vector<SvgShape> fixed = fixedShapes(input);
  ASSERT_EQ(fixed.size(), 2u);
  Drawing drawing;
  drawing.viewBox = input.viewBox;
  DrawingGroup group{"fixed", "", {}, drawnShapes(fixed), {}};
  group.markup = input.fixedMarkup;
  drawing.groups.push_back(group);
  drawing.groups.push_back({"elements", "", {}, {}, {}});
  const std::string svg = toSvgString(drawing);
  for (const std::string& text : {kPath, kCircle, kRadial, kStops}) EXPECT_NE(svg.find(text), std::string::npos) << text;
  EXPECT_NE(svg.find("xmlns:sodipodi=\"http://sodipodi.sourceforge.net/DTD/sodipodi-0.dtd\""), std::string::npos);
  EXPECT_NE(svg.find("xmlns:xlink=\"http://www.w3.org/1999/xlink\""), std::string::npos);
  EXPECT_EQ(svg.find("xmlns:inkscape", svg.find("xmlns:inkscape") + 1), std::string::npos);  // declared once

  SvgDocument output = readSvgString(svg, "out.svg");  // throws on malformed XML
  const std::vector<SvgShape> back = fixedShapes(output);
  ASSERT_EQ(back.size(), fixed.size());
  for (std::size_t i = 0; i < fixed.size(); ++i) {
    EXPECT_EQ(back[i].fill, fixed[i].fill) << i;  // the gradient resolves the same way
    EXPECT_EQ(back[i].stroke, fixed[i].stroke) << i;
    EXPECT_NEAR(back[i].strokeWidth, fixed[i].strokeWidth, 1e-9) << i;
    EXPECT_NEAR(back[i].opacity, fixed[i].opacity, 1e-9) << i;
    ASSERT_EQ(back[i].subpaths.size(), fixed[i].subpaths.size()) << i;
    for (std::size_t k = 0; k < fixed[i].subpaths.size(); ++k) {
      ASSERT_EQ(back[i].subpaths[k].points.size(), fixed[i].subpaths[k].points.size());
      for (std::size_t p = 0; p < fixed[i].subpaths[k].points.size(); ++p)
        EXPECT_LE(distance(back[i].subpaths[k].points[p], fixed[i].subpaths[k].points[p]), 1e-6);
    }
  }
  // Copied once: reading the copy again gives the same markup content inside the new wrapper.
  EXPECT_NE(output.fixedMarkup.content.find(kPath), std::string::npos);
}

TEST(FixedMarkup, ConflictingPrefixIsDeclaredOnTheCopyItself) {
  const std::string svg = R"~(<svg xmlns="http://www.w3.org/2000/svg" xmlns:inkscape="urn:other" viewBox="0 0 10 10">
<g id="fixed"><rect x="1" y="1" width="2" height="2" inkscape:odd="1"/></g></svg>)~";
  SvgDocument input = readSvgString(svg, "odd.svg");
  ASSERT_FALSE(input.fixedMarkup.empty());
  Drawing drawing;
  drawing.viewBox = input.viewBox;
  DrawingGroup group{"fixed", "", {}, drawnShapes(fixedShapes(input)), {}};
  group.markup = input.fixedMarkup;
  drawing.groups.push_back(group);
  const std::string out = toSvgString(drawing);
  EXPECT_NE(out.find("<g id=\"fixed\" inkscape:groupmode=\"layer\" inkscape:label=\"fixed\" xmlns:inkscape=\"urn:other\">"),
            std::string::npos) << out;
  EXPECT_NE(out.find(R"~(<rect x="1" y="1" width="2" height="2" inkscape:odd="1"/>)~"), std::string::npos);
  EXPECT_EQ(fixedShapes(readSvgString(out, "out.svg")).size(), 1u);
}

TEST(FixedMarkup, StylesheetsAndHiddenLayersAreNotCopied) {
  const std::string styled = R"~(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><style>.a{fill:red}</style>
<g id="fixed"><rect class="a" x="1" y="1" width="2" height="2"/></g></svg>)~";
  SvgDocument document = readSvgString(styled, "styled.svg");
  EXPECT_TRUE(document.fixedMarkup.empty());  // the copy would lose the class's colour: re-drawn
  EXPECT_EQ(fixedShapes(document).size(), 1u);
  const std::string hidden = R"~(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">
<g id="fixed" style="display:none"><rect x="1" y="1" width="2" height="2"/></g></svg>)~";
  EXPECT_TRUE(readSvgString(hidden, "hidden.svg").fixedMarkup.empty());
}

}  // namespace
}  // namespace pak
