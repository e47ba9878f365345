#include "io/xml_nesting.hpp"

#include <gtest/gtest.h>

#include <string>

#include "pak/error.hpp"

namespace pak {
namespace {

// `levels` elements, each inside the one before; the innermost empty (<rect/>) when asked.
std::string nested(int levels, bool emptyInnermost) {
  std::string text;
  for (int i = 0; i < levels - (emptyInnermost ? 1 : 0); ++i) text += "<g>";
  if (emptyInnermost) text += "<rect/>";
  for (int i = 0; i < levels - (emptyInnermost ? 1 : 0); ++i) text += "</g>";
  return text;
}

TEST(XmlNesting, TheLimitIsAllowedAndOneMoreIsAnErrorWithItsLine) {
  EXPECT_NO_THROW(checkXmlNesting(nested(256, false), "a.svg"));
  EXPECT_NO_THROW(checkXmlNesting(nested(256, true), "a.svg"));
  EXPECT_THROW(checkXmlNesting(nested(257, false), "a.svg"), InputError);
  try {
    checkXmlNesting("<svg>\n" + nested(256, true) + "</svg>", "a.svg");
    FAIL() << "an empty element one level too deep was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("a.svg:2: elements nested more than 256 deep", 0), 0u) << e.what();
  }
}

TEST(XmlNesting, CommentsCdataDeclarationsAndQuotedBracketsDoNotCount) {
  std::string text = "<?xml version=\"1.0\"?><!DOCTYPE svg [<!ENTITY a \"<g>\">]><!-- <g><g> -->";
  text += "<svg a=\"<g>\"><![CDATA[<g><g><g>]]>" + nested(255, true) + "</svg>";
  EXPECT_NO_THROW(checkXmlNesting(text, "a.svg"));
}

TEST(XmlNesting, ClosingTagsOfSiblingsKeepTheDepth) {
  std::string text = "<svg>";
  for (int i = 0; i < 10000; ++i) text += "<g><rect/></g>";
  EXPECT_NO_THROW(checkXmlNesting(text + "</svg>", "a.svg", 3));
}

}  // namespace
}  // namespace pak
