#include "core/mcap_writer.h"

#include <algorithm>
#include <stdexcept>

#include "core/crc32.h"

namespace cosim {

const char kMcapMagic[8] = {'\x89', 'M', 'C', 'A', 'P', '0', '\r', '\n'};

namespace {

// Serialization (specification, "Serialization"): little-endian integers; strings and byte
// arrays prefixed by their uint32 length (a chunk's records by a uint64 one).
void u8(std::string& b, std::uint8_t v) {
  b += static_cast<char>(v);
}
void u16(std::string& b, std::uint16_t v) {
  for (int i = 0; i < 2; ++i) b += static_cast<char>((v >> (8 * i)) & 0xff);
}
void u32(std::string& b, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) b += static_cast<char>((v >> (8 * i)) & 0xff);
}
void u64(std::string& b, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) b += static_cast<char>((v >> (8 * i)) & 0xff);
}
void str(std::string& b, const std::string& s) {
  if (s.size() > 0xffffffffu) throw std::length_error("MCAP string over 4 GiB");
  u32(b, static_cast<std::uint32_t>(s.size()));
  b += s;
}

// <opcode><uint64 content length><content>
std::string record(McapOp op, const std::string& content) {
  std::string r;
  u8(r, static_cast<std::uint8_t>(op));
  u64(r, content.size());
  return r + content;
}

}  // namespace

McapWriter::McapWriter(const std::string& profile, const std::string& library,
                       std::size_t chunk_bytes)
    : chunk_bytes_(std::max<std::size_t>(chunk_bytes, 1024)) {
  file_.assign(kMcapMagic, sizeof kMcapMagic);
  std::string header;
  str(header, profile);
  str(header, library);
  file_ += record(McapOp::Header, header);
}

std::uint16_t McapWriter::addSchema(const std::string& name, const std::string& encoding,
                                    const std::string& data) {
  const auto id = static_cast<std::uint16_t>(schemas_.size() + 1);  // 0 means "no schema"
  std::string c;
  u16(c, id);
  str(c, name);
  str(c, encoding);
  str(c, data);
  schemas_.push_back(record(McapOp::Schema, c));
  chunk_ += schemas_.back();  // before any channel that refers to it
  return id;
}

std::uint16_t McapWriter::addChannel(std::uint16_t schema, const std::string& topic,
                                     const std::string& message_encoding,
                                     const std::map<std::string, std::string>& metadata) {
  const auto id = static_cast<std::uint16_t>(channels_.size());
  std::string c, map;
  u16(c, id);
  u16(c, schema);
  str(c, topic);
  str(c, message_encoding);
  for (const auto& [k, v] : metadata) {
    str(map, k);
    str(map, v);
  }
  str(c, map);
  channels_.push_back(record(McapOp::Channel, c));
  chunk_ += channels_.back();
  return id;
}

void McapWriter::addMessage(std::uint16_t channel, std::uint64_t log_time,
                            const std::string& data) {
  std::string c;
  u16(c, channel);
  u32(c, sequence_++);
  u64(c, log_time);
  u64(c, log_time);
  c += data;
  chunk_index_[channel].emplace_back(log_time, chunk_.size());
  chunk_ += record(McapOp::Message, c);
  if (!chunk_has_messages_) chunk_start_ = chunk_end_ = log_time;
  chunk_start_ = std::min(chunk_start_, log_time);
  chunk_end_ = std::max(chunk_end_, log_time);
  chunk_has_messages_ = true;
  if (message_count_ == 0) first_time_ = last_time_ = log_time;
  first_time_ = std::min(first_time_, log_time);
  last_time_ = std::max(last_time_, log_time);
  ++message_count_;
  ++channel_counts_[channel];
  if (chunk_.size() >= chunk_bytes_) closeChunk();
}

// The open chunk (uncompressed, with the CRC of its records), then one Message Index record per
// channel with messages in it.
void McapWriter::closeChunk() {
  if (chunk_.empty()) return;
  ChunkIndexEntry e;
  e.start_time = chunk_has_messages_ ? chunk_start_ : 0;
  e.end_time = chunk_has_messages_ ? chunk_end_ : 0;
  e.records_size = chunk_.size();
  std::string c;
  u64(c, e.start_time);
  u64(c, e.end_time);
  u64(c, chunk_.size());
  u32(c, crc32(chunk_));
  str(c, "");  // no compression
  u64(c, chunk_.size());
  c += chunk_;
  e.offset = file_.size();
  file_ += record(McapOp::Chunk, c);
  e.length = file_.size() - e.offset;
  const std::size_t index_start = file_.size();
  for (const auto& [channel, entries] : chunk_index_) {
    std::string m, list;
    u16(m, channel);
    for (const auto& [time, offset] : entries) {
      u64(list, time);
      u64(list, offset);
    }
    str(m, list);
    e.index_offsets[channel] = file_.size();
    file_ += record(McapOp::MessageIndex, m);
  }
  e.index_length = file_.size() - index_start;
  chunks_.push_back(e);
  chunk_.clear();
  chunk_index_.clear();
  chunk_has_messages_ = false;
}

std::string McapWriter::finish() {
  closeChunk();
  // Data End: the CRC of every byte before it, from the file's first (the leading magic), as
  // the reference readers compute it.
  std::string data_end;
  u32(data_end, crc32(file_));
  file_ += record(McapOp::DataEnd, data_end);

  const std::uint64_t summary_start = file_.size();
  std::vector<std::pair<McapOp, std::pair<std::uint64_t, std::uint64_t>>> groups;
  const auto group = [&](McapOp op, const std::vector<std::string>& records) {
    if (records.empty()) return;
    const std::uint64_t start = file_.size();
    for (const std::string& r : records) file_ += r;
    groups.push_back({op, {start, file_.size() - start}});
  };
  group(McapOp::Schema, schemas_);
  group(McapOp::Channel, channels_);
  std::vector<std::string> indexes;
  for (const ChunkIndexEntry& e : chunks_) {
    std::string c, offsets;
    u64(c, e.start_time);
    u64(c, e.end_time);
    u64(c, e.offset);
    u64(c, e.length);
    for (const auto& [channel, offset] : e.index_offsets) {
      u16(offsets, channel);
      u64(offsets, offset);
    }
    str(c, offsets);
    u64(c, e.index_length);
    str(c, "");
    u64(c, e.records_size);  // compressed size = uncompressed: no compression
    u64(c, e.records_size);
    indexes.push_back(record(McapOp::ChunkIndex, c));
  }
  group(McapOp::ChunkIndex, indexes);
  std::string stats, counts;
  u64(stats, message_count_);
  u16(stats, static_cast<std::uint16_t>(schemas_.size()));
  u32(stats, static_cast<std::uint32_t>(channels_.size()));
  u32(stats, 0);  // attachments
  u32(stats, 0);  // metadata
  u32(stats, static_cast<std::uint32_t>(chunks_.size()));
  u64(stats, message_count_ ? first_time_ : 0);
  u64(stats, message_count_ ? last_time_ : 0);
  for (const auto& [channel, n] : channel_counts_) {
    u16(counts, channel);
    u64(counts, n);
  }
  str(stats, counts);
  group(McapOp::Statistics, {record(McapOp::Statistics, stats)});

  const std::uint64_t offsets_start = file_.size();
  for (const auto& [op, where] : groups) {
    std::string c;
    u8(c, static_cast<std::uint8_t>(op));
    u64(c, where.first);
    u64(c, where.second);
    file_ += record(McapOp::SummaryOffset, c);
  }
  // Footer: its summary CRC covers the summary and summary offset sections and the footer's
  // own fields before it (opcode and length included).
  std::string footer;
  u8(footer, static_cast<std::uint8_t>(McapOp::Footer));
  u64(footer, 8 + 8 + 4);
  u64(footer, summary_start);
  u64(footer, offsets_start);
  const std::string summary = file_.substr(summary_start) + footer;
  u32(footer, crc32(summary));
  file_ += footer;
  file_.append(kMcapMagic, sizeof kMcapMagic);
  return std::move(file_);
}

}  // namespace cosim
