// Reference keypoints from TensorFlow.js for the pose parity test: runs the same MoveNet graph
// model (with its own in-graph decoder) on 192x192 RGB inputs (binary PPM files written by the
// pose_inputs tool) with the WASM backend on one thread, offline.
//   node scripts/pose-reference.js MODEL_DIR OUT.tsv INPUT.ppm...
// Needs @tensorflow/tfjs-core, -converter and -backend-wasm 4.22.0 installed outside the
// repository, found through NODE_PATH (scripts/pose-parity.sh does both).
'use strict';
const fs = require('fs');
const path = require('path');
const tf = require('@tensorflow/tfjs-core');
const converter = require('@tensorflow/tfjs-converter');
const wasm = require('@tensorflow/tfjs-backend-wasm');

function readPpm(file) {
  const buf = fs.readFileSync(file);
  const header = buf.toString('latin1', 0, 64).match(/^P6\s+(\d+)\s+(\d+)\s+255\s/);
  if (!header) throw new Error(`${file}: not a binary PPM`);
  const [w, h] = [Number(header[1]), Number(header[2])];
  const pixels = buf.subarray(header[0].length, header[0].length + w * h * 3);
  return { w, h, data: Int32Array.from(pixels) };
}

async function main() {
  const [modelDir, out, ...inputs] = process.argv.slice(2);
  if (!modelDir || !out || inputs.length === 0) {
    console.error('usage: node scripts/pose-reference.js MODEL_DIR OUT.tsv INPUT.ppm...');
    process.exit(2);
  }
  const wasmDir = path.dirname(require.resolve('@tensorflow/tfjs-backend-wasm'));
  wasm.setWasmPaths(wasmDir + path.sep);
  wasm.setThreadsCount(1);
  await tf.setBackend('wasm');
  await tf.ready();
  const json = JSON.parse(fs.readFileSync(path.join(modelDir, 'movenet-lightning.json')));
  const weights = fs.readFileSync(path.join(modelDir, 'movenet-lightning.bin'));
  const handler = {
    load: async () => ({
      modelTopology: json.modelTopology,
      weightSpecs: json.weightsManifest[0].weights,
      weightData: weights.buffer.slice(weights.byteOffset, weights.byteOffset + weights.length),
      format: json.format,
      generatedBy: json.generatedBy,
      convertedBy: json.convertedBy,
    }),
  };
  const model = await converter.loadGraphModel(handler);
  const lines = ['# MoveNet keypoints from TensorFlow.js (WASM backend, one thread) for the ' +
                 '192x192 network input of each frame: y x score per keypoint, y and x in 0..1',
                 '# made by scripts/pose-parity.sh'];
  for (const file of inputs) {
    const img = readPpm(file);
    const out4 = tf.tidy(() => model.execute(tf.tensor4d(img.data, [1, img.h, img.w, 3], 'int32')));
    const k = await out4.data();
    out4.dispose();
    const values = Array.from(k, (v) => v.toFixed(6));
    lines.push([path.basename(file, '.ppm'), ...values].join('\t'));
  }
  fs.writeFileSync(out, lines.join('\n') + '\n');
}

main().catch((e) => {
  console.error(e.stack || String(e));
  process.exit(1);
});
