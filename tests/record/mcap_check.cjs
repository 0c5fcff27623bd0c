// Reads an MCAP file with the MCAP project's own reader (@mcap/core, from
// npm) in both its ways: the streaming reader (every record in file order,
// CRCs checked) and the indexed reader (the summary, chunk indexes, message
// indexes, as Foxglove reads a file). Prints one JSON object on stdout:
// schemas, channels (topic -> schema), messages per topic from each reader,
// the metadata, the first message of each topic parsed as JSON and every
// /events message as "name: message".
// Usage: node mcap_check.cjs NODE_MODULES_DIR FILE.mcap
"use strict";
const path = require("path");
const fs = require("fs");
const [modules, file] = process.argv.slice(2);
const { McapStreamReader, McapIndexedReader } = require(path.join(modules, "@mcap/core"));

async function main() {
  const bytes = fs.readFileSync(file);
  const out = { stream: {}, indexed: {}, schemas: {}, channels: {}, metadata: {}, first: {}, events: [], parse_errors: 0 };
  const decoder = new TextDecoder();

  // 1. Streaming, CRCs validated.
  const stream = new McapStreamReader({ validateCrcs: true });
  stream.append(new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength));
  const topics = new Map();
  let record;
  while ((record = stream.nextRecord()) !== undefined) {
    if (record.type === "Channel") topics.set(record.id, record.topic);
    if (record.type === "Message") {
      const t = topics.get(record.channelId);
      out.stream[t] = (out.stream[t] || 0) + 1;
    }
  }
  out.stream_done = stream.done();

  // 2. Indexed: the summary's schemas, channels, statistics; every message.
  const readable = {
    size: async () => BigInt(bytes.byteLength),
    read: async (offset, size) => new Uint8Array(bytes.buffer, bytes.byteOffset + Number(offset), Number(size)),
  };
  const reader = await McapIndexedReader.Initialize({ readable });
  for (const [id, s] of reader.schemasById) out.schemas[s.name] = s.encoding;
  for (const [id, c] of reader.channelsById) {
    out.channels[c.topic] = {
      schema: reader.schemasById.get(c.schemaId).name,
      encoding: c.messageEncoding,
    };
  }
  out.statistics_messages = Number(reader.statistics.messageCount);
  out.chunks = reader.chunkIndexes.length;
  let last = -1n;
  out.ordered = true;
  for await (const m of reader.readMessages({ validateCrcs: true })) {
    const topic = reader.channelsById.get(m.channelId).topic;
    out.indexed[topic] = (out.indexed[topic] || 0) + 1;
    if (m.logTime < last || m.publishTime !== m.logTime) out.ordered = false;
    last = m.logTime;
    try {
      const value = JSON.parse(decoder.decode(m.data));
      if (!(topic in out.first)) out.first[topic] = value;
      if (topic === "/events") out.events.push(value.name + ": " + value.message);
    } catch (e) {
      out.parse_errors += 1;
    }
  }
  for await (const md of reader.readMetadata()) out.metadata[md.name] = Object.fromEntries(md.metadata);
  process.stdout.write(JSON.stringify(out));
}

main().catch((e) => {
  process.stderr.write("mcap_check: " + (e && e.stack ? e.stack : e) + "\n");
  process.exit(1);
});
