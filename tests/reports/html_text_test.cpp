#include "reports/html_text.h"

#include <gtest/gtest.h>

namespace gib::reports {
namespace {

TEST(HtmlText, EscapesEveryCharacterThatEndsTextOrAnAttribute) {
  EXPECT_EQ(escapeHtml(R"(<a href="x">'&'</a>)"),
            "&lt;a href=&quot;x&quot;&gt;&#39;&amp;&#39;&lt;/a&gt;");
  EXPECT_EQ(escapeHtml("cornell-direct/shadow=pcf,light_samples=4"),
            "cornell-direct/shadow=pcf,light_samples=4");
}

TEST(HtmlText, UrlPathsKeepSlashesAndEncodeTheRest) {
  EXPECT_EQ(urlPath("report/cornell-direct__shadow-pcf.html"),
            "report/cornell-direct__shadow-pcf.html");
  EXPECT_EQ(urlPath("jobs/a b#c?d%e=f,g/image.png"), "jobs/a%20b%23c%3Fd%25e%3Df%2Cg/image.png");
  EXPECT_EQ(urlPath("caf\xc3\xa9"), "caf%C3%A9");
}

}  // namespace
}  // namespace gib::reports
