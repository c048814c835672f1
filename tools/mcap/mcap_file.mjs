// Opening MCAP files: a rosbag2 bag is a directory (metadata.yaml + *.mcap) or a bare .mcap file.
// rosbag2 compresses chunks with zstd by default (lz4 optionally); both are decoded here.
import { open, readdir, stat } from "node:fs/promises";
import path from "node:path";

import { McapIndexedReader } from "@mcap/core";
import { FileHandleReadable } from "@mcap/nodejs";
import zstd from "@foxglove/wasm-zstd";
import lz4 from "@foxglove/wasm-lz4";

/// The .mcap files of a bag: the file itself, or every *.mcap in a bag directory, sorted.
export async function mcapFiles(bagPath) {
  const info = await stat(bagPath).catch(() => {
    throw new Error(`${bagPath}: cannot open (no such file or directory)`);
  });
  if (!info.isDirectory()) return [bagPath];
  const names = (await readdir(bagPath)).filter((n) => n.endsWith(".mcap")).sort();
  if (names.length === 0) throw new Error(`${bagPath}: a bag directory without any .mcap file`);
  return names.map((n) => path.join(bagPath, n));
}

/// Opens one file for indexed reading; `close()` releases it.
export async function openMcap(file) {
  await zstd.isLoaded;
  await lz4.isLoaded;
  const handle = await open(file, "r");
  try {
    const reader = await McapIndexedReader.Initialize({
      readable: new FileHandleReadable(handle),
      decompressHandlers: {
        zstd: (data, size) => zstd.decompress(data, Number(size)),
        lz4: (data, size) => lz4(data, Number(size)),
      },
    });
    return { reader, close: () => handle.close() };
  } catch (err) {
    await handle.close();
    // Indexed reading needs the summary a finished recording ends with; a recording cut off
    // (crash, power loss) lacks it: `mcap recover` (the MCAP CLI) rewrites it whole.
    throw new Error(
      `${file}: not a readable MCAP file, or one without its summary (a recording cut off: ` +
        `repair it with \`mcap recover\`) (${err.message})`,
    );
  }
}
