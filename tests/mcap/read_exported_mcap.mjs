// Reads a run exported by `cosim export-mcap` with the MCAP reference reader (@mcap/core's
// McapIndexedReader: footer, summary and chunk indexes, seeking) and checks what Foxglove
// needs: the schemas and channels, messages on every topic in time order, CRCs that verify,
// and JSON payloads of the Foxglove well-known types.
// Usage: node read_exported_mcap.mjs FILE.mcap NODE_MODULES_DIR
import { createRequire } from "node:module";
import { open } from "node:fs/promises";
import path from "node:path";

const [file, modules] = process.argv.slice(2);
const require = createRequire(path.join(modules, "noop.js"));
const { McapIndexedReader } = require("@mcap/core");
const { crc32 } = require("@foxglove/crc");

function check(ok, what) {
  if (!ok) {
    console.error("FAILED: " + what);
    process.exit(1);
  }
}

const handle = await open(file, "r");
const size = (await handle.stat()).size;
const readable = {
  size: async () => BigInt(size),
  read: async (offset, length) => {
    const buffer = new Uint8Array(Number(length));
    await handle.read(buffer, 0, Number(length), Number(offset));
    return buffer;
  },
};
const reader = await McapIndexedReader.Initialize({ readable });  // checks the summary CRC

const schemas = [...reader.schemasById.values()].map((s) => s.name).sort();
for (const name of ["foxglove.FrameTransform", "foxglove.SceneUpdate", "cosim.VehicleState"])
  check(schemas.includes(name), `schema ${name} in ${schemas}`);
for (const s of reader.schemasById.values()) {
  check(s.encoding === "jsonschema", `schema ${s.name} encoding ${s.encoding}`);
  check(JSON.parse(new TextDecoder().decode(s.data)).title === s.name, `schema ${s.name} title`);
}
const topics = new Map([...reader.channelsById.values()].map((c) => [c.id, c.topic]));
for (const t of ["/world", "/vehicles", "/paths", "/tf", "/moments"])
  check([...topics.values()].includes(t), `channel ${t}`);
check(reader.chunkIndexes.length >= 1, "chunk indexes");

// The data section's CRC as the reference writer computes it: every byte before Data End.
const head = await readable.read(0n, reader.dataEndOffset);
check(reader.dataSectionCrc === crc32(head), `data section CRC ${reader.dataSectionCrc}`);

let count = 0, last = -1n, transforms = 0, scenes = 0;
const perTopic = new Map();
for await (const m of reader.readMessages({ validateCrcs: true })) {
  check(m.logTime >= last, "messages in time order");
  last = m.logTime;
  const topic = topics.get(m.channelId);
  perTopic.set(topic, (perTopic.get(topic) ?? 0) + 1);
  const body = JSON.parse(new TextDecoder().decode(m.data));
  if (topic === "/tf") {
    transforms++;
    check(body.parent_frame_id === "world" && typeof body.child_frame_id === "string", "transform frames");
    const q = body.rotation;
    check(Math.abs(Math.hypot(q.x, q.y, q.z, q.w) - 1) < 1e-6, "unit rotation");
  }
  if (topic === "/world") {
    scenes++;
    const e = body.entities[0];
    check(e.cubes.length + e.cylinders.length + e.spheres.length > 1, "world has floor and obstacles");
  }
  count++;
}
check(count === Number(reader.statistics.messageCount), `read ${count} of ${reader.statistics.messageCount}`);
check(count > 100, `more than 100 messages (${count})`);
check(transforms > 50 && scenes === 1, `transforms ${transforms}, world scenes ${scenes}`);

// Seeking: the second half of the run alone, through the chunk indexes.
const middle = reader.statistics.messageEndTime / 2n;
let later = 0;
for await (const m of reader.readMessages({ topics: ["/tf"], startTime: middle })) {
  check(m.logTime >= middle, "seek starts at the requested time");
  later++;
}
check(later > 0 && later < transforms, `seek found ${later} of ${transforms} transforms`);
console.log(`read ${count} messages on ${topics.size} channels (${[...perTopic].map(([t, n]) => `${t} ${n}`).join(", ")})`);
await handle.close();
