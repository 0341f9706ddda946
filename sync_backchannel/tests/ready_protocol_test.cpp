// The READY line format and the resynchronising parser, as pure logic. Expected checksums were
// computed outside this code (a separate CRC-8/SMBUS implementation) and are also in the docs.
#include "sync_backchannel/ready_protocol.hpp"

#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace l2 {
namespace {

const Message kReady123{MessageKind::Ready, 123};

TEST(Crc8, MatchesTheStandardCheckValue) {
  EXPECT_EQ(crc8("123456789"), 0xF4);
}

TEST(FormatMessage, ProducesTheDocumentedLines) {
  EXPECT_EQ(format_message(MessageKind::Ready, 0), "READY 000000 26\r\n");
  EXPECT_EQ(format_message(MessageKind::Ready, 1), "READY 000001 21\r\n");
  EXPECT_EQ(format_message(MessageKind::Ready, 123), "READY 000123 6E\r\n");
  EXPECT_EQ(format_message(MessageKind::Ready, 999999), "READY 999999 25\r\n");
  EXPECT_EQ(format_message(MessageKind::SyncRequest, 0), "SYNC? 000000 EE\r\n");
  EXPECT_EQ(format_message(MessageKind::SyncRequest, 123), "SYNC? 000123 A6\r\n");
  EXPECT_EQ(format_message(MessageKind::Ready, 123).size(), kMessageBytes);
}

TEST(FormatMessage, WrapsFrameNumbersModuloAMillion) {
  EXPECT_EQ(format_message(MessageKind::Ready, 1'000'123), "READY 000123 6E\r\n");
}

TEST(MessageParser, DecodesOneMessage) {
  MessageParser parser;
  EXPECT_EQ(parser.feed("READY 000123 6E\r\n"), std::vector<Message>{kReady123});
  EXPECT_EQ(parser.feed("SYNC? 000000 EE\r\n"),
            (std::vector<Message>{{MessageKind::SyncRequest, 0}}));
  EXPECT_EQ(parser.counts().messages, 2u);
  EXPECT_EQ(parser.counts().noise_bytes, 0u);
  EXPECT_EQ(parser.counts().resyncs, 0u);
}

TEST(MessageParser, DecodesAMessageSplitAtEveryByteBoundary) {
  const std::string line = "READY 000123 6E\r\n";
  for (std::size_t cut = 0; cut <= line.size(); ++cut) {
    MessageParser parser;
    std::vector<Message> got = parser.feed(line.substr(0, cut));
    if (cut < line.size()) {
      EXPECT_TRUE(got.empty()) << "cut " << cut;
      EXPECT_EQ(parser.pending(), cut) << "cut " << cut;
    }
    const std::vector<Message> rest = parser.feed(line.substr(cut));
    got.insert(got.end(), rest.begin(), rest.end());
    EXPECT_EQ(got, std::vector<Message>{kReady123}) << "cut " << cut;
    EXPECT_EQ(parser.counts().noise_bytes, 0u);
  }
}

TEST(MessageParser, DecodesWhenFedOneByteAtATime) {
  const std::string stream = "READY 000001 21\r\nSYNC? 000123 A6\r\nREADY 999999 25\r\n";
  MessageParser parser;
  std::vector<Message> got;
  for (char c : stream) {
    const std::vector<Message> m = parser.feed(std::string(1, c));
    got.insert(got.end(), m.begin(), m.end());
  }
  EXPECT_EQ(got, (std::vector<Message>{{MessageKind::Ready, 1},
                                       {MessageKind::SyncRequest, 123},
                                       {MessageKind::Ready, 999999}}));
}

TEST(MessageParser, SkipsNoiseBeforeAndAfter) {
  MessageParser parser;
  EXPECT_EQ(parser.feed("xyz\x01\xff READY 000123 6E\r\n\r\n##"), std::vector<Message>{kReady123});
  EXPECT_EQ(parser.counts().noise_bytes, 5u + 1u + 4u);
  EXPECT_EQ(parser.counts().resyncs, 0u);
}

TEST(MessageParser, ResynchronisesAfterNoiseInsideAMessage) {
  MessageParser parser;
  // A message cut by a glitch, immediately followed by a whole one.
  EXPECT_EQ(parser.feed("READY 00#READY 000123 6E\r\n"), std::vector<Message>{kReady123});
  EXPECT_EQ(parser.counts().resyncs, 1u);
  EXPECT_EQ(parser.counts().noise_bytes, 9u);  // "READY 00" and '#'
}

TEST(MessageParser, AStartMarkerThatBreaksAMessageStartsTheNextOne) {
  MessageParser parser;
  // The partial "REA" is lost at the second 'R', which begins a valid message.
  EXPECT_EQ(parser.feed("REAREADY 000123 6E\r\n"), std::vector<Message>{kReady123});
  EXPECT_EQ(parser.counts().resyncs, 1u);
  EXPECT_EQ(parser.counts().noise_bytes, 3u);
  // Same for a SYNC? cut short by a READY.
  MessageParser parser2;
  EXPECT_EQ(parser2.feed("SYNC? 0001READY 000123 6E\r\n"), std::vector<Message>{kReady123});
  EXPECT_EQ(parser2.counts().noise_bytes, 10u);
}

TEST(MessageParser, CountsABadChecksumAndDropsTheLine) {
  MessageParser parser;
  EXPECT_TRUE(parser.feed("READY 000124 6E\r\n").empty());  // one digit flipped
  EXPECT_EQ(parser.counts().bad_checksums, 1u);
  EXPECT_EQ(parser.counts().messages, 0u);
  EXPECT_EQ(parser.feed("READY 000123 6E\r\n"), std::vector<Message>{kReady123});
}

TEST(MessageParser, RejectsLowercaseHexAndBareLineFeeds) {
  MessageParser parser;
  EXPECT_TRUE(parser.feed("READY 000123 6e\r\n").empty());
  EXPECT_TRUE(parser.feed("READY 000123 6E\n").empty());
  EXPECT_EQ(parser.counts().messages, 0u);
  EXPECT_EQ(parser.counts().resyncs, 2u);
  EXPECT_EQ(parser.counts().noise_bytes, 17u + 16u);
}

TEST(MessageParser, RecoversEveryMessageFromRandomNoiseBetweenThem) {
  // Noise never contains 'R' or 'S' here, so every message must come through.
  std::mt19937 rng(1234);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_int_distribution<int> gap(0, 40);
  std::string stream;
  std::vector<Message> sent;
  std::uint64_t noise = 0;
  for (std::uint32_t frame = 0; frame < 500; ++frame) {
    for (int i = gap(rng); i > 0; --i) {
      char c;
      do c = static_cast<char>(byte(rng));
      while (c == 'R' || c == 'S');
      stream += c;
      ++noise;
    }
    const MessageKind kind = frame % 7 == 3 ? MessageKind::SyncRequest : MessageKind::Ready;
    stream += format_message(kind, frame * 1999u);
    sent.push_back({kind, frame * 1999u % kFrameModulus});
  }
  // Fed in random-sized chunks, so messages are split at arbitrary places.
  MessageParser parser;
  std::vector<Message> got;
  std::uniform_int_distribution<std::size_t> chunk(1, 64);
  for (std::size_t at = 0; at < stream.size();) {
    const std::size_t n = std::min(chunk(rng), stream.size() - at);
    const std::vector<Message> m = parser.feed(std::string_view(stream).substr(at, n));
    got.insert(got.end(), m.begin(), m.end());
    at += n;
  }
  EXPECT_EQ(got, sent);
  EXPECT_EQ(parser.counts().noise_bytes, noise);
  EXPECT_EQ(parser.counts().bad_checksums, 0u);
}

TEST(MessageParser, AccountsForEveryByteOfArbitraryGarbage) {
  // Arbitrary bytes, markers included, mixed with valid messages: nothing crashes and every
  // byte ends up in a message, a bad-checksum line, noise or the pending partial message.
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> byte(0, 255);
  std::string stream;
  for (int i = 0; i < 20000; ++i) {
    if (i % 97 == 0) stream += format_message(MessageKind::Ready, static_cast<std::uint64_t>(i));
    const int b = byte(rng);
    // Bias towards protocol characters so the parser gets deep into partial messages.
    stream += b < 128 ? "READY 0123456789ABCDEF\r\n?SYNC"[b % 30] : static_cast<char>(b);
  }
  MessageParser parser;
  const std::vector<Message> got = parser.feed(stream);
  const ParserCounts& c = parser.counts();
  EXPECT_EQ(got.size(), c.messages);
  // All 207 planted messages survive: a start marker never fits inside a message, so garbage
  // before one cannot swallow it (random garbage forming an extra valid line is also fine).
  EXPECT_GE(c.messages, 207u);
  EXPECT_EQ(c.messages * kMessageBytes + c.bad_checksums * kMessageBytes + c.noise_bytes +
                parser.pending(),
            stream.size());
}

TEST(ToString, ShowsTheLineWithoutChecksum) {
  EXPECT_EQ(to_string(kReady123), "READY 000123");
  EXPECT_EQ(to_string(Message{MessageKind::SyncRequest, 7}), "SYNC? 000007");
}

}  // namespace
}  // namespace l2
