#include "base/svg.h"

#include <gtest/gtest.h>

#include <string>

namespace acdplan {
namespace {

TEST(SvgCanvas, MapsWorldToPixelsWithTheYAxisDown) {
  SvgCanvasOptions options;
  options.pixels = 100;
  options.margin = 10;
  // 4 x 2 units: 25 pixels per unit.
  SvgCanvas canvas(Eigen::AlignedBox2d(Eigen::Vector2d(-2, 1), Eigen::Vector2d(2, 3)), options);
  EXPECT_EQ(canvas.scale(), 25.0);
  EXPECT_EQ(canvas.X(-2), "10");
  EXPECT_EQ(canvas.X(2), "110");
  EXPECT_EQ(canvas.Y(3), "10");  // the top of the world is the top of the picture
  EXPECT_EQ(canvas.Y(1), "60");
  EXPECT_EQ(canvas.PathData({{{-2, 1}, {2, 1}, {2, 3}}, {{0, 2}, {1, 2}, {1, 2.5}}}),
            "M10,60 L110,60 L110,10 Z M60,35 L85,35 L85,22.5 Z");
}

TEST(SvgCanvas, FinishesWithTitleBackgroundElementsAndEscapedCaption) {
  SvgCanvas canvas(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1)));
  canvas.Add("<circle r=\"1\"/>\n");
  const std::string svg = canvas.Finish({"a<b & c", "second line"}, "t\"itle");
  EXPECT_EQ(svg.rfind("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"820\"", 0), 0u) << svg;
  EXPECT_NE(svg.find("<title>t&quot;itle</title>"), std::string::npos);
  EXPECT_NE(svg.find("<circle r=\"1\"/>"), std::string::npos);
  EXPECT_NE(svg.find(">a&lt;b &amp; c</text>"), std::string::npos);
  EXPECT_NE(svg.find(">second line</text>"), std::string::npos);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
}

TEST(SvgCanvas, WidensForALongCaptionAndSurvivesAnEmptyDrawing) {
  SvgCanvas empty{Eigen::AlignedBox2d()};
  const std::string svg = empty.Finish({std::string(300, 'x')});
  // 300 characters at 0.55 x 14 px: 2310 px plus the margins.
  EXPECT_NE(svg.find("width=\"2330\""), std::string::npos) << svg.substr(0, 120);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_EQ(svg.find("inf"), std::string::npos);
}

TEST(Svg, EscapesXmlAndDropsControlCharacters) {
  EXPECT_EQ(EscapeXml("<a href='x'>&\"\x01\tok\n"),
            "&lt;a href=&apos;x&apos;&gt;&amp;&quot;\tok\n");
}

TEST(Svg, ComponentFillsAreDistinctHexColours) {
  for (int k = 0; k < 20; ++k) {
    const std::string fill = ComponentFill(k);
    ASSERT_EQ(fill.size(), 7u);
    EXPECT_EQ(fill[0], '#');
    EXPECT_NE(fill, ComponentFill(k + 1));
  }
}

}  // namespace
}  // namespace acdplan
