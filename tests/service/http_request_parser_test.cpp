// The epoll engine's HTTP/1.1 request parser (service/http_request_parser.hpp): requests
// in every split of their bytes, pipelining, chunked bodies, limits and malformed input.
#include "service/http_request_parser.hpp"

#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace bezier::service {
namespace {

using State = HttpRequestParser::State;

constexpr ParserLimits kLimits{256, 64};

struct Outcome {
  State state = State::need_more;
  std::size_t used = 0;  ///< bytes of the input given to this request, over all pieces
  // The request's fields are views into the parser's storage: the parser stays alive.
  std::shared_ptr<HttpRequestParser> parser;
  [[nodiscard]] const HttpRequest& request() const { return parser->request(); }
  [[nodiscard]] const ParseError& error() const { return parser->error(); }
};

// Feeds `input` in pieces of `piece` bytes until the request completes or fails.
Outcome parse(std::string_view input, std::size_t piece = 1 << 20, ParserLimits limits = kLimits) {
  Outcome outcome;
  outcome.parser = std::make_shared<HttpRequestParser>(limits);
  HttpRequestParser& parser = *outcome.parser;
  for (std::size_t at = 0; at < input.size();) {
    const std::string_view part = input.substr(at, std::min(piece, input.size() - at));
    const auto progress = parser.feed(part);
    outcome.used += progress.used;
    at += progress.used;
    outcome.state = progress.state;
    if (progress.state != State::need_more) break;
    EXPECT_EQ(progress.used, part.size()) << "need_more must use every byte";
  }
  return outcome;
}

TEST(HttpRequestParser, GetWithHeaders) {
  const auto o = parse("GET /healthz?verbose=1 HTTP/1.1\r\nHost: x\r\nX-Request-Id:  abc \t\r\n\r\n");
  ASSERT_EQ(o.state, State::complete);
  EXPECT_EQ(o.request().method, "GET");
  EXPECT_EQ(o.request().target, "/healthz?verbose=1");
  EXPECT_EQ(o.request().path, "/healthz");
  EXPECT_EQ(o.request().minor_version, 1);
  EXPECT_EQ(o.request().header("x-request-id"), "abc");  // case-insensitive, trimmed
  EXPECT_EQ(o.request().header("HOST"), "x");
  EXPECT_EQ(o.request().header("Absent"), "");
  EXPECT_TRUE(o.request().keep_alive);
  EXPECT_TRUE(o.request().body.empty());
}

TEST(HttpRequestParser, EverySplitOfAPostGivesTheSameRequest) {
  const std::string body = R"({"points":[[0,0],[1,1]],"t":0.5})";
  const std::string chunked_body = "5\r\n" + body.substr(0, 5) + "\r\n" + "1a;ext=1\r\n" + body.substr(5, 26) +
                                   "\r\n" + "1\r\n" + body.substr(31) + "\r\n0\r\nTrailer: t\r\n\r\n";
  ASSERT_EQ(body.size(), 32u);
  const std::vector<std::string> inputs = {
      "POST /evaluate HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: 32\r\n\r\n" + body,
      "POST /evaluate HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nTransfer-Encoding: chunked\r\n\r\n" +
          chunked_body,
  };
  for (const std::string& input : inputs) {
    // Two pieces, split at every position; then one byte at a time.
    for (std::size_t split = 0; split <= input.size(); ++split) {
      HttpRequestParser parser(kLimits);
      auto first = parser.feed(std::string_view(input).substr(0, split));
      std::size_t used = first.used;
      if (first.state == State::need_more) used += parser.feed(std::string_view(input).substr(split)).used;
      ASSERT_EQ(used, input.size()) << "split at " << split;
      EXPECT_EQ(parser.request().body, body) << "split at " << split;
      EXPECT_EQ(parser.request().header("content-type"), "application/json");
    }
    const auto o = parse(input, 1);
    ASSERT_EQ(o.state, State::complete);
    EXPECT_EQ(o.used, input.size());
    EXPECT_EQ(o.request().body, body);
  }
}

TEST(HttpRequestParser, PipelinedRequestsAreTakenOneAtATime) {
  const std::string one = "POST /a HTTP/1.1\r\nHost: x\r\nContent-Length: 3\r\n\r\nabc";
  const std::string two = "GET /b HTTP/1.1\r\nHost: x\r\n\r\n";
  const std::string three = "GET /c HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n";
  const std::string stream = one + two + three;
  HttpRequestParser parser(kLimits);
  std::string_view rest(stream);
  std::vector<std::string> paths;
  while (!rest.empty()) {
    const auto progress = parser.feed(rest);
    ASSERT_EQ(progress.state, State::complete);
    paths.emplace_back(parser.request().path);
    rest.remove_prefix(progress.used);
    if (paths.size() == 1) {
      EXPECT_EQ(parser.request().body, "abc");
    }
    if (paths.size() == 3) {
      EXPECT_FALSE(parser.request().keep_alive);
    }
    parser.reset();
  }
  EXPECT_EQ(paths, (std::vector<std::string>{"/a", "/b", "/c"}));
}

TEST(HttpRequestParser, IncompleteInputNeedsMore) {
  for (const std::string_view input :
       {"G", "GET / HTTP/1.1", "GET / HTTP/1.1\r\n", "GET / HTTP/1.1\r\nHost: x\r\n\r",
        "POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 3\r\n\r\nab", "POST / HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\n3\r\nab",
        "POST / HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\n0\r\n"}) {
    HttpRequestParser parser(kLimits);
    const auto progress = parser.feed(input);
    EXPECT_EQ(progress.state, State::need_more) << input;
    EXPECT_EQ(progress.used, input.size()) << input;
    EXPECT_TRUE(parser.started()) << input;
  }
}

TEST(HttpRequestParser, LeadingEmptyLinesAreIgnoredAndDoNotStartARequest) {
  HttpRequestParser parser(kLimits);
  EXPECT_EQ(parser.feed("\r\n").state, State::need_more);
  EXPECT_FALSE(parser.started());
  EXPECT_EQ(parser.feed("GET / HTTP/1.1\r\nHost: x\r\n\r\n").state, State::complete);
}

TEST(HttpRequestParser, AwaitingBodyAfterTheHeadOfAnExpectContinueRequest) {
  HttpRequestParser parser(kLimits);
  const auto progress = parser.feed("POST / HTTP/1.1\r\nHost: x\r\nExpect: 100-Continue\r\nContent-Length: 5\r\n\r\n");
  EXPECT_EQ(progress.state, State::need_more);
  EXPECT_TRUE(parser.awaiting_body());
  EXPECT_TRUE(parser.request().expect_continue);
  EXPECT_EQ(parser.feed("12345").state, State::complete);
  EXPECT_FALSE(parser.awaiting_body());
}

TEST(HttpRequestParser, KeepAliveFollowsTheVersionAndConnectionHeader) {
  EXPECT_TRUE(parse("GET / HTTP/1.1\r\nHost: x\r\n\r\n").request().keep_alive);
  EXPECT_FALSE(parse("GET / HTTP/1.1\r\nHost: x\r\nConnection: Close\r\n\r\n").request().keep_alive);
  EXPECT_FALSE(parse("GET / HTTP/1.0\r\n\r\n").request().keep_alive);
  EXPECT_TRUE(parse("GET / HTTP/1.0\r\nConnection: keep-alive\r\n\r\n").request().keep_alive);
  EXPECT_FALSE(parse("GET / HTTP/1.1\r\nHost: x\r\nConnection: upgrade, close\r\n\r\n").request().keep_alive);
  EXPECT_EQ(parse("GET / HTTP/1.0\r\n\r\n").request().minor_version, 0);
}

TEST(HttpRequestParser, BodyOverTheLimitIsRefusedBeforeItIsRead) {
  // kLimits.max_body_bytes is 64: the head alone decides.
  const auto o = parse("POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 65\r\n\r\n");
  ASSERT_EQ(o.state, State::error);
  EXPECT_EQ(o.error().status, 413);
  EXPECT_EQ(parse("POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 99999999999999999999999999\r\n\r\n").error().status, 413);
  EXPECT_EQ(parse("POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 64\r\n\r\n" + std::string(64, 'x')).state, State::complete);
  // Chunked: the decoded size counts, over all chunks.
  EXPECT_EQ(parse("POST / HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\n20\r\n" + std::string(32, 'x') +
                  "\r\n21\r\n")
                .error().status,
            413);
  EXPECT_EQ(parse("POST / HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\nffffffffffffffffffff\r\n").error().status, 413);
}

TEST(HttpRequestParser, HeadOverTheLimitIs431AndALongRequestLine414) {
  const std::string big_header = "GET / HTTP/1.1\r\nHost: x\r\nX-Pad: " + std::string(300, 'a') + "\r\n\r\n";
  EXPECT_EQ(parse(big_header).error().status, 431);
  EXPECT_EQ(parse(big_header, 7).error().status, 431);
  const std::string long_line = "GET /" + std::string(300, 'a') + " HTTP/1.1\r\nHost: x\r\n\r\n";
  EXPECT_EQ(parse(long_line).error().status, 414);
  // Exactly at the limit is fine.
  const std::string head = "GET / HTTP/1.1\r\nHost: x\r\nX-Pad: ";
  const std::string fits = head + std::string(kLimits.max_head_bytes - head.size() - 4, 'a') + "\r\n\r\n";
  ASSERT_EQ(fits.size(), kLimits.max_head_bytes);
  EXPECT_EQ(parse(fits).state, State::complete);
  EXPECT_EQ(parse(fits, 3).state, State::complete);
}

TEST(HttpRequestParser, MalformedRequestsAre400) {
  for (const std::string_view input : {
           "GET\r\n\r\n",                                    // no target, no version
           "GET  / HTTP/1.1\r\nHost: x\r\n\r\n",                        // two spaces
           "GET / HTTP/1.1 x\r\n\r\n",                       // three parts
           "GET / HTTP/1\r\n\r\n",                           // malformed version
           "GET / FTP/1.1\r\n\r\n",                          //
           "G(T / HTTP/1.1\r\nHost: x\r\n\r\n",                         // not a token
           "GET evaluate HTTP/1.1\r\nHost: x\r\n\r\n",                  // neither origin nor absolute form
           "GET / HTTP/1.1\r\nHost: x\r\nNo colon\r\n\r\n",             //
           "GET / HTTP/1.1\r\nHost: x\r\nBad name: x\r\n\r\n",          // space in a name
           "GET / HTTP/1.1\r\nHost: x\r\nName : x\r\n\r\n",             // space before the colon
           "GET / HTTP/1.1\r\nHost: x\r\nA: b\r\n folded\r\n\r\n",      // obs-fold
           "GET / HTTP/1.1\r\nHost: x\r\nA: b\x01\r\n\r\n",             // control character
           "POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 1x\r\n\r\n",  //
           "POST / HTTP/1.1\r\nHost: x\r\nContent-Length: -1\r\n\r\n",  //
           "POST / HTTP/1.1\r\nHost: x\r\nContent-Length:\r\n\r\n",     //
           "POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 1\r\nContent-Length: 2\r\n\r\n",
           "POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 1\r\nTransfer-Encoding: chunked\r\n\r\n",  // smuggling
           "POST / HTTP/1.0\r\nTransfer-Encoding: chunked\r\n\r\n",
           "POST / HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\nzz\r\n",      // not hex
           "POST / HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\n\r\n",        // no size
           "POST / HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\n1\r\nab\r\n",  // data longer than size
           "POST / HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\n1\n",          // bare LF
           "GET / HTTP/1.1\nHost: x\n\n",                                // bare LF line ends
           "GET / HTTP/1.1\r\nHost: x\n\r\n",                            // one bare LF
           "GET / HTTP/1.1\nHost: x\r\n",                                // a bare LF, head not yet complete
           "GET / HTTP/1.1\r\nHost: x\r\nAuthorization: Bearer a\r\nauthorization: Bearer b\r\n\r\n",
       }) {
    const auto o = parse(input);
    EXPECT_EQ(o.state, State::error) << input;
    EXPECT_EQ(o.error().status, 400) << input;
    EXPECT_FALSE(o.error().detail.empty()) << input;
  }
}

TEST(HttpRequestParser, UnsupportedVersionAndCodingsHaveTheirStatus) {
  EXPECT_EQ(parse("GET / HTTP/2.0\r\n\r\n").error().status, 505);
  EXPECT_EQ(parse("GET / HTTP/1.2\r\n\r\n").error().status, 505);
  EXPECT_EQ(parse("POST / HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: gzip, chunked\r\n\r\n").error().status, 501);
  EXPECT_EQ(parse("POST / HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: gzip\r\n\r\n").error().status, 501);
}

TEST(HttpRequestParser, AgreeingContentLengthsAreOneLength) {
  const auto o = parse("POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 2\r\ncontent-length: 2\r\n\r\nok");
  ASSERT_EQ(o.state, State::complete);
  EXPECT_EQ(o.request().body, "ok");
}

TEST(HttpRequestParser, ResetKeepsNothingOfThePreviousRequest) {
  HttpRequestParser parser(kLimits);
  ASSERT_EQ(parser.feed("POST /a HTTP/1.0\r\nContent-Length: 2\r\nExpect: 100-continue\r\n\r\nhi").state,
            State::complete);
  parser.reset();
  EXPECT_FALSE(parser.started());
  ASSERT_EQ(parser.feed("GET /b HTTP/1.1\r\nHost: x\r\n\r\n").state, State::complete);
  EXPECT_EQ(parser.request().path, "/b");
  EXPECT_TRUE(parser.request().body.empty());
  EXPECT_TRUE(parser.request().keep_alive);
  EXPECT_FALSE(parser.request().expect_continue);
  EXPECT_EQ(parser.request().header("content-length"), "");
}

TEST(HttpRequestParser, AbsoluteFormTargetIsRoutedByItsPath) {
  // RFC 9112 §3.2.2: a server must accept the absolute form; the path is what is routed,
  // the target stays as sent.
  const auto o = parse("GET http://example.com:8080/evaluate?x=1 HTTP/1.1\r\nHost: example.com:8080\r\n\r\n");
  ASSERT_EQ(o.state, State::complete) << o.error().detail;
  EXPECT_EQ(o.request().target, "http://example.com:8080/evaluate?x=1");
  EXPECT_EQ(o.request().path, "/evaluate");
  // The scheme is case-insensitive (RFC 3986 §3.1); an empty path is "/".
  EXPECT_EQ(parse("GET HTTPS://h/a/b HTTP/1.1\r\nHost: h\r\n\r\n").request().path, "/a/b");
  EXPECT_EQ(parse("GET http://h HTTP/1.1\r\nHost: h\r\n\r\n").request().path, "/");
  EXPECT_EQ(parse("GET http://h?q=1 HTTP/1.1\r\nHost: h\r\n\r\n").request().path, "/");
  EXPECT_EQ(parse("GET http://[::1]:80/healthz HTTP/1.1\r\nHost: [::1]:80\r\n\r\n").request().path, "/healthz");
  for (const std::string_view target : {"ftp://h/x", "http:/h/x", "http:h/x", "http:///x", "http://?q",
                                        "http://user@h/x", "h/x", "mailto:a"}) {
    const auto refused = parse("GET " + std::string(target) + " HTTP/1.1\r\nHost: h\r\n\r\n");
    EXPECT_EQ(refused.state, State::error) << target;
    EXPECT_EQ(refused.error().status, 400) << target;
  }
}

TEST(HttpRequestParser, Http11NeedsExactlyOneValidHost) {
  // RFC 9112 §3.2: 400 for an HTTP/1.1 request without Host, and for any request with more
  // than one Host or an invalid one.
  for (const std::string_view input : {"GET / HTTP/1.1\r\n\r\n",
                                       "GET / HTTP/1.1\r\nHost: a\r\nHost: a\r\n\r\n",
                                       "GET / HTTP/1.1\r\nHost: a\r\nhost: b\r\n\r\n",
                                       "GET / HTTP/1.0\r\nHost: a\r\nHost: b\r\n\r\n",
                                       "GET / HTTP/1.1\r\nHost: a/b\r\n\r\n",
                                       "GET / HTTP/1.1\r\nHost: a\"b\r\n\r\n",
                                       "GET http://h/ HTTP/1.1\r\n\r\n"}) {
    const auto o = parse(input);
    EXPECT_EQ(o.state, State::error) << input;
    EXPECT_EQ(o.error().status, 400) << input;
    EXPECT_FALSE(o.error().detail.empty()) << input;
  }
  // HTTP/1.0 may leave it out; an empty Host (a target URI without authority) is valid.
  for (const std::string_view input : {"GET / HTTP/1.0\r\n\r\n", "GET / HTTP/1.1\r\nHost:\r\n\r\n",
                                       "GET / HTTP/1.1\r\nHost: example.com:8080\r\n\r\n",
                                       "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n",
                                       "GET / HTTP/1.1\r\nHost: [::1]:8080\r\n\r\n"}) {
    EXPECT_EQ(parse(input).state, State::complete) << input;
  }
}

TEST(HttpRequestParser, ContentEncodingInTwoLinesIsRefused) {
  // One line is the router's to judge (415 unless identity); two leave it ambiguous which
  // codings a reader applies.
  const std::string head = "POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 2\r\n";
  const auto two = parse(head + "Content-Encoding: identity\r\nContent-Encoding: gzip\r\n\r\nok");
  EXPECT_EQ(two.state, State::error);
  EXPECT_EQ(two.error().status, 400);
  const auto one = parse(head + "Content-Encoding: gzip\r\n\r\nok");
  ASSERT_EQ(one.state, State::complete);
  EXPECT_EQ(one.request().header("content-encoding"), "gzip");
}

TEST(HttpRequestParser, AfterAnErrorNothingMoreIsTaken) {
  HttpRequestParser parser(kLimits);
  ASSERT_EQ(parser.feed("BAD\r\n\r\n").state, State::error);
  const auto again = parser.feed("GET / HTTP/1.1\r\nHost: x\r\n\r\n");
  EXPECT_EQ(again.state, State::error);
  EXPECT_EQ(again.used, 0u);
}

}  // namespace
}  // namespace bezier::service
