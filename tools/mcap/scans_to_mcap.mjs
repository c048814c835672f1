#!/usr/bin/env node
// Writes shelfdock scan JSON Lines (e.g. from `shelfdock bag --out`) as a ROS 2 recording: one
// MCAP file with sensor_msgs/msg/LaserScan in CDR on one topic, zstd-compressed chunks, as
// `ros2 bag record` writes with its default MCAP storage.
//   node tools/mcap/scans_to_mcap.mjs --scans scans.jsonl --topic /scan --out scans.mcap [--max N]
// Log time = publish time = the scan's stamp.
import { createReadStream } from "node:fs";
import { open } from "node:fs/promises";
import { createInterface } from "node:readline";
import { parseArgs } from "node:util";

import { McapWriter } from "@mcap/core";
import { FileHandleWritable } from "@mcap/nodejs";
import zstd from "@foxglove/wasm-zstd";

import { SCHEMA_NAME, SCHEMA_TEXT, makeWriter, scanToMessage, stampToRos } from "./laser_scan.mjs";

const USAGE = "usage: scans_to_mcap.mjs --scans FILE.jsonl --topic TOPIC --out FILE.mcap [--max N]";
const REQUIRED = ["angle_min", "angle_max", "angle_increment", "range_min", "range_max", "ranges"];

function checkScan(scan, where) {
  for (const key of REQUIRED) {
    if (!(key in scan)) throw new Error(`${where}: missing field ${key}`);
  }
  if (!Array.isArray(scan.ranges)) throw new Error(`${where}: field ranges: expected an array`);
}

function stampNs(stamp_s) {
  const { sec, nanosec } = stampToRos(stamp_s ?? 0);
  return BigInt(sec) * 1000000000n + BigInt(nanosec);
}

async function main() {
  const { values } = parseArgs({
    options: {
      scans: { type: "string" },
      topic: { type: "string" },
      out: { type: "string" },
      max: { type: "string" },
    },
  });
  for (const key of ["scans", "topic", "out"]) {
    if (values[key] === undefined) throw new Error(`--${key} is required\n${USAGE}`);
  }
  const max = values.max === undefined ? Infinity : Number(values.max);
  if (!(max >= 1)) throw new Error(`--max: expected a positive whole number, got ${values.max}`);

  const input = createReadStream(values.scans);
  await new Promise((resolve, reject) => {
    input.once("open", resolve);
    input.once("error", (e) => reject(new Error(`${values.scans}: cannot open file (${e.code})`)));
  });
  await zstd.isLoaded;
  const handle = await open(values.out, "w").catch((e) => {
    throw new Error(`${values.out}: cannot write file (${e.code})`);
  });
  const writer = new McapWriter({
    writable: new FileHandleWritable(handle),
    compressChunk: (data) => ({ compression: "zstd", compressedData: zstd.compress(data, 3) }),
  });
  await writer.start({ profile: "ros2", library: "shelfdock tools/mcap" });
  const schemaId = await writer.registerSchema({
    name: SCHEMA_NAME,
    encoding: "ros2msg",
    data: new TextEncoder().encode(SCHEMA_TEXT),
  });
  const channelId = await writer.registerChannel({
    topic: values.topic,
    schemaId,
    messageEncoding: "cdr",
    metadata: new Map(),
  });
  const cdr = makeWriter();

  let line_no = 0;
  let written = 0;
  for await (const line of createInterface({ input, crlfDelay: Infinity })) {
    ++line_no;
    if (line.trim() === "") continue;
    const where = `${values.scans}:${line_no}`;
    let scan;
    try {
      scan = JSON.parse(line);
    } catch (e) {
      throw new Error(`${where}: not JSON (${e.message})`);
    }
    checkScan(scan, where);
    const time = stampNs(scan.stamp);
    await writer.addMessage({
      channelId,
      sequence: written,
      logTime: time,
      publishTime: time,
      data: cdr.writeMessage(scanToMessage(scan)),
    });
    if (++written >= max) break;
  }
  await writer.end();
  await handle.close();
  input.destroy();
  const summary = { scans: values.scans, topic: values.topic, messages: written, out: values.out };
  process.stdout.write(JSON.stringify(summary) + "\n");
}

main().catch((err) => {
  process.stderr.write(`error: ${err.message}\n`);
  process.exitCode = 2;
});
