// What the TensorFlow.js reference scripts share (scripts/pose-reference.js,
// scripts/blazepose-reference.js): reading a binary PPM the input tools wrote, and loading a
// graph model from armmimic's model folder onto the WASM backend with one thread, offline.
// Needs @tensorflow/tfjs-core, -converter and -backend-wasm 4.22.0 through NODE_PATH.
'use strict';
const fs = require('fs');
const path = require('path');
const tf = require('@tensorflow/tfjs-core');
const converter = require('@tensorflow/tfjs-converter');
const wasm = require('@tensorflow/tfjs-backend-wasm');

// { w, h, pixels }: the PPM's size and its RGB bytes.
function readPpm(file) {
  const buf = fs.readFileSync(file);
  const header = buf.toString('latin1', 0, 64).match(/^P6\s+(\d+)\s+(\d+)\s+255\s/);
  if (!header) throw new Error(`${file}: not a binary PPM`);
  const [w, h] = [Number(header[1]), Number(header[2])];
  return { w, h, pixels: buf.subarray(header[0].length, header[0].length + w * h * 3) };
}

// The graph model NAME.json / NAME.bin of MODEL_DIR, on the WASM backend with one thread.
async function loadWasmModel(modelDir, name) {
  const wasmDir = path.dirname(require.resolve('@tensorflow/tfjs-backend-wasm'));
  wasm.setWasmPaths(wasmDir + path.sep);
  wasm.setThreadsCount(1);
  await tf.setBackend('wasm');
  await tf.ready();
  const json = JSON.parse(fs.readFileSync(path.join(modelDir, `${name}.json`)));
  const weights = fs.readFileSync(path.join(modelDir, `${name}.bin`));
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
  return converter.loadGraphModel(handler);
}

module.exports = { tf, readPpm, loadWasmModel };
