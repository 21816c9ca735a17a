// The MCAP writer's record structure read back byte by byte: magic at both ends, opcodes and
// lengths that tile the file, the chunk, data-section and summary CRCs, and indexes that point at
// the records they name.
#include "core/mcap_writer.h"

#include <gtest/gtest.h>

#include <cstring>
#include <set>

#include "core/base64.h"
#include "core/crc32.h"

using namespace cosim;

namespace {

std::uint64_t le(const std::string& b, std::size_t at, int bytes) {
  std::uint64_t v = 0;
  for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(b.at(at + i));
  return v;
}

struct Record {
  std::uint8_t op;
  std::size_t start;  // of the opcode
  std::string content;
};

// The records between the magics, in order; fails the test if they do not tile the file.
std::vector<Record> records(const std::string& f) {
  std::vector<Record> out;
  std::size_t at = 8;
  while (at < f.size() - 8) {
    const auto op = static_cast<std::uint8_t>(f.at(at));
    const std::uint64_t len = le(f, at + 1, 8);
    EXPECT_LE(at + 9 + len, f.size() - 8) << "record at " << at << " runs past the end";
    if (at + 9 + len > f.size() - 8) break;
    out.push_back({op, at, f.substr(at + 9, len)});
    at += 9 + len;
  }
  EXPECT_EQ(at, f.size() - 8);
  return out;
}

std::string sampleFile(int messages, std::size_t chunk_bytes) {
  McapWriter w("", "cosim test", chunk_bytes);
  const auto schema = w.addSchema("foxglove.FrameTransform", "jsonschema", "{\"type\":\"object\"}");
  const auto a = w.addChannel(schema, "/tf", "json");
  const auto b = w.addChannel(schema, "/other", "json", {{"k", "v"}});
  for (int i = 0; i < messages; ++i)
    w.addMessage(i % 3 == 0 ? b : a, 1000000ull * i, "{\"i\":" + std::to_string(i) + "}");
  return w.finish();
}

}  // namespace

TEST(Crc32, MatchesTheStandardCheckValueAndContinues) {
  EXPECT_EQ(crc32(std::string_view("123456789")), 0xCBF43926u);
  EXPECT_EQ(crc32(std::string_view("6789"), crc32(std::string_view("12345"))), 0xCBF43926u);
  EXPECT_EQ(crc32(std::string_view("")), 0u);
}

TEST(Base64, EncodesWithPaddingAsTheRfcExamples) {
  const auto enc = [](const std::string& s) {
    return base64Encode(reinterpret_cast<const std::uint8_t*>(s.data()), s.size());
  };
  EXPECT_EQ(enc(""), "");
  EXPECT_EQ(enc("f"), "Zg==");
  EXPECT_EQ(enc("fo"), "Zm8=");
  EXPECT_EQ(enc("foo"), "Zm9v");
  EXPECT_EQ(enc("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64Encode({0xff, 0xfe, 0x00}), "//4A");
}

TEST(McapWriter, RecordsTileTheFileBetweenTheMagics) {
  const std::string f = sampleFile(300, 2048);
  ASSERT_GT(f.size(), 16u);
  EXPECT_EQ(f.substr(0, 8), std::string(kMcapMagic, 8));
  EXPECT_EQ(f.substr(f.size() - 8), std::string(kMcapMagic, 8));
  EXPECT_EQ(std::memcmp(f.data(), "\x89MCAP0\r\n", 8), 0);
  const auto r = records(f);
  ASSERT_GE(r.size(), 5u);
  EXPECT_EQ(r.front().op, 0x01);               // Header
  EXPECT_EQ(le(r.front().content, 0, 4), 0u);  // empty profile
  EXPECT_EQ(r.front().content.substr(8), "cosim test");
  EXPECT_EQ(r.back().op, 0x02);  // Footer
  EXPECT_EQ(r.back().content.size(), 20u);
}

TEST(McapWriter, ChunksCarryTheirMessagesWithValidCrcsAndIndexes) {
  const std::string f = sampleFile(300, 2048);
  const auto r = records(f);
  std::size_t messages = 0, chunks = 0, data_end = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (r[i].op == 0x0F) data_end = i;
    if (r[i].op != 0x06) continue;
    ++chunks;
    const std::string& c = r[i].content;
    const std::uint64_t size = le(c, 16, 8);
    const auto crc = static_cast<std::uint32_t>(le(c, 24, 4));
    EXPECT_EQ(le(c, 28, 4), 0u);  // compression ""
    EXPECT_EQ(le(c, 32, 8), size);
    const std::string inner = c.substr(40);
    ASSERT_EQ(inner.size(), size);
    EXPECT_EQ(crc, crc32(inner));
    for (std::size_t at = 0; at < inner.size(); at += 9 + le(inner, at + 1, 8))
      if (inner[at] == 0x05) ++messages;
  }
  EXPECT_EQ(messages, 300u);
  EXPECT_GT(chunks, 1u) << "a 2 KiB chunk limit splits 300 messages";
  ASSERT_GT(data_end, 0u);
  EXPECT_EQ(le(r[data_end].content, 0, 4), crc32(f.data(), r[data_end].start))
      << "Data End's CRC covers every byte before it";
}

TEST(McapWriter, SummaryIndexesPointAtTheirRecords) {
  const std::string f = sampleFile(120, 1024);
  const auto r = records(f);
  const std::string& footer = r.back().content;
  const std::uint64_t summary_start = le(footer, 0, 8), offsets_start = le(footer, 8, 8);
  ASSERT_GT(summary_start, 0u);
  ASSERT_GT(offsets_start, summary_start);
  EXPECT_EQ(le(footer, 16, 4),
            crc32(f.data() + summary_start, r.back().start + 25 - summary_start));
  std::set<int> grouped;
  std::uint64_t stats_messages = 0;
  for (const Record& rec : r) {
    if (rec.op == 0x0B) stats_messages = le(rec.content, 0, 8);
    if (rec.op == 0x0E) {  // Summary Offset: the group's first record has its opcode
      const int op = static_cast<unsigned char>(rec.content[0]);
      grouped.insert(op);
      EXPECT_EQ(static_cast<unsigned char>(f.at(le(rec.content, 1, 8))), op);
    }
    if (rec.op == 0x08) {  // Chunk Index -> a Chunk, and its message indexes -> Message Index
      EXPECT_EQ(f.at(le(rec.content, 16, 8)), 0x06);
      const std::string& c = rec.content;
      const std::uint64_t map_bytes = le(c, 32, 4);
      for (std::size_t at = 36; at < 36 + map_bytes; at += 10)
        EXPECT_EQ(f.at(le(c, at + 2, 8)), 0x07);
    }
  }
  EXPECT_EQ(stats_messages, 120u);
  EXPECT_EQ(grouped, (std::set<int>{0x03, 0x04, 0x08, 0x0B}));
}
