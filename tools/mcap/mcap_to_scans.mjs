#!/usr/bin/env node
// Reads sensor_msgs/msg/LaserScan from a ROS 2 recording (rosbag2 MCAP: a bag directory or a
// .mcap file) and writes shelfdock's scan JSON Lines, one scan per line, in log-time order.
//   node tools/mcap/mcap_to_scans.mjs BAG                 lists the LaserScan topics (JSON)
//   node tools/mcap/mcap_to_scans.mjs BAG --topic /scan [--out scans.jsonl] [--max N]
// Without --out (or with --out -) the scans go to stdout, e.g. into `shelfdock detect`.
// Exit codes as shelfdock's: 0 ok, 2 bad input (the message names the file or option).
import { createWriteStream } from "node:fs";
import { parseArgs } from "node:util";

import { mcapFiles, openMcap } from "./mcap_file.mjs";
import { SCHEMA_NAME, makeReader, messageToScan } from "./laser_scan.mjs";

const USAGE = "usage: mcap_to_scans.mjs BAG [--topic TOPIC] [--out FILE|-] [--max N]";

function scanChannels(reader) {
  const out = [];
  for (const channel of reader.channelsById.values()) {
    const schema = reader.schemasById.get(channel.schemaId);
    if (!schema || schema.name !== SCHEMA_NAME) continue;
    const messages = reader.statistics?.channelMessageCounts.get(channel.id) ?? null;
    out.push({ channel, schema, messages: messages === null ? null : Number(messages) });
  }
  return out;
}

async function listTopics(bag, files) {
  const topics = new Map();
  for (const file of files) {
    const { reader, close } = await openMcap(file);
    for (const { channel, messages } of scanChannels(reader)) {
      const prev = topics.get(channel.topic) ?? 0;
      topics.set(channel.topic, messages === null || prev === null ? null : prev + messages);
    }
    await close();
  }
  const list = [...topics].map(([topic, messages]) => ({ topic, messages }));
  process.stdout.write(JSON.stringify({ bag, laser_scan_topics: list }) + "\n");
}

async function writeScans(bag, files, topic, out, max) {
  let written = 0;
  let found = false;
  for (const file of files) {
    if (written >= max) break;
    const { reader, close } = await openMcap(file);
    const channels = scanChannels(reader).filter((c) => c.channel.topic === topic);
    const readers = new Map();
    for (const { channel, schema } of channels) {
      if (channel.messageEncoding !== "cdr") {
        throw new Error(`${file}: topic ${topic} is encoded as ${channel.messageEncoding}, not cdr`);
      }
      readers.set(channel.id, makeReader(new TextDecoder().decode(schema.data)));
    }
    found ||= channels.length > 0;
    if (channels.length > 0) {
      for await (const message of reader.readMessages({ topics: [topic] })) {
        const scan = messageToScan(readers.get(message.channelId).readMessage(message.data));
        if (!out.write(JSON.stringify(scan) + "\n")) {
          await new Promise((resolve) => out.once("drain", resolve));
        }
        if (++written >= max) break;
      }
    }
    await close();
  }
  if (!found) throw new Error(`${bag}: no ${SCHEMA_NAME} topic named ${topic} (list them: omit --topic)`);
  return written;
}

async function main() {
  const { values, positionals } = parseArgs({
    allowPositionals: true,
    options: { topic: { type: "string" }, out: { type: "string" }, max: { type: "string" } },
  });
  if (positionals.length !== 1) throw new Error(USAGE);
  const bag = positionals[0];
  const max = values.max === undefined ? Infinity : Number(values.max);
  if (!(max >= 1) || !Number.isInteger(max) && max !== Infinity) {
    throw new Error(`--max: expected a positive whole number, got ${values.max}`);
  }
  const files = await mcapFiles(bag);
  if (values.topic === undefined) return listTopics(bag, files);

  const toStdout = values.out === undefined || values.out === "-";
  const out = toStdout ? process.stdout : createWriteStream(values.out);
  if (!toStdout) {
    await new Promise((resolve, reject) => {
      out.once("open", resolve);
      out.once("error", (e) => reject(new Error(`${values.out}: cannot write file (${e.code})`)));
    });
  }
  const written = await writeScans(bag, files, values.topic, out, max);
  if (!toStdout) {
    await new Promise((resolve) => out.end(resolve));
    const summary = { bag, topic: values.topic, scans: written, out: values.out };
    process.stdout.write(JSON.stringify(summary) + "\n");
  }
}

main().catch((err) => {
  process.stderr.write(`error: ${err.message}\n`);
  process.exitCode = 2;
});
