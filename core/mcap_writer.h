#pragma once
// An MCAP file writer (the published MCAP format specification, major version 0): magic, Header,
// a data section of uncompressed Chunks each followed by its Message Index records, Data End,
// a summary section (Schema, Channel, Chunk Index and Statistics records, grouped by opcode),
// Summary Offset records, Footer, magic. Readers can seek: the Chunk Indexes point at every chunk
// and its message indexes. The whole file is built in memory; finish() hands it out.
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace cosim {

// Record opcodes (specification, "Records").
enum class McapOp : std::uint8_t {
  Header = 0x01,
  Footer = 0x02,
  Schema = 0x03,
  Channel = 0x04,
  Message = 0x05,
  Chunk = 0x06,
  MessageIndex = 0x07,
  ChunkIndex = 0x08,
  Statistics = 0x0B,
  SummaryOffset = 0x0E,
  DataEnd = 0x0F,
};

// The 8 bytes at both ends of every MCAP file: 0x89 "MCAP" '0' "\r\n".
extern const char kMcapMagic[8];

class McapWriter {
 public:
  // profile: the Header's profile ("" for none); library: the writer's name and version.
  // chunk_bytes: a chunk is closed once its records reach this size.
  explicit McapWriter(const std::string& profile, const std::string& library,
                      std::size_t chunk_bytes = 1 << 20);

  // Returns the new schema's id (1, 2, ...).
  std::uint16_t addSchema(const std::string& name, const std::string& encoding,
                          const std::string& data);
  // Returns the new channel's id (0, 1, ...). schema: an id from addSchema, or 0 for none.
  std::uint16_t addChannel(std::uint16_t schema, const std::string& topic,
                           const std::string& message_encoding,
                           const std::map<std::string, std::string>& metadata = {});
  // log_time in nanoseconds; publish_time is the same.
  void addMessage(std::uint16_t channel, std::uint64_t log_time, const std::string& data);

  std::uint64_t messageCount() const { return message_count_; }

  // Closes the last chunk and returns the whole file. Call once.
  std::string finish();

 private:
  struct ChunkIndexEntry {
    std::uint64_t start_time, end_time, offset, length;
    std::map<std::uint16_t, std::uint64_t> index_offsets;
    std::uint64_t index_length, records_size;
  };
  void closeChunk();

  std::string file_;  // magic, header and every closed chunk so far
  std::size_t chunk_bytes_;
  std::string chunk_;  // records of the open chunk
  std::uint64_t chunk_start_ = 0, chunk_end_ = 0;
  bool chunk_has_messages_ = false;
  std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunk_index_;
  std::vector<std::string> schemas_, channels_;  // their records, for the summary
  std::vector<ChunkIndexEntry> chunks_;
  std::map<std::uint16_t, std::uint64_t> channel_counts_;
  std::uint64_t message_count_ = 0, first_time_ = 0, last_time_ = 0;
  std::uint32_t sequence_ = 0;
};

}  // namespace cosim
