// Which values --cors-origin takes (service/config.hpp, is_cors_origin): "*", or an
// origin serialized as browsers send it in the Origin header (RFC 6454 §6.2: lower-case
// scheme "://" host [":" port], nothing after), so that a configured value can match a
// request's Origin exactly; anything else stops start-up instead of never matching.
#include <gtest/gtest.h>

#include "service/config.hpp"

namespace bezier::service {
namespace {

TEST(CorsOrigin, OriginsAsBrowsersSendThemAreTaken) {
  for (const char* value : {"*", "https://app.example", "http://localhost:5173", "https://tools.example:8443",
                            "http://127.0.0.1:8080", "http://[::1]:3000", "https://a.example:65535",
                            "https://a-b.example.co.uk",
                            "chrome-extension://abcdefghijklmnop", "web+app://x"}) {
    EXPECT_TRUE(is_cors_origin(value)) << value;
  }
}

TEST(CorsOrigin, ValuesThatNoOriginHeaderCouldEqualAreRefused) {
  for (const char* value : {"", "**", "app.example", "https://", "://app.example", "https://app.example/",
                            "https://app.example/path", "https://app.example?x", "https://app.example#x",
                            "HTTPS://app.example", "https://App.Example", "https://app example", "1http://x",
                            "https://user@app.example", "null", "https://a.example:99999",
                            "https://a.example:65536", "https://a.example:", "https://a.example:8a",
                            "https://a.example:1:2", "http://[::1", "http://[::1]x", "http://::1:80",
                            "https://:443"}) {
    EXPECT_FALSE(is_cors_origin(value)) << value;
  }
}

}  // namespace
}  // namespace bezier::service
