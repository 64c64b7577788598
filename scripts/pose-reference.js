// Reference keypoints from TensorFlow.js for the pose parity test: runs the same MoveNet graph
// model (with its own in-graph decoder) on 192x192 RGB inputs (binary PPM files written by the
// pose_inputs tool) with the WASM backend on one thread, offline.
//   node scripts/pose-reference.js MODEL_DIR OUT.tsv INPUT.ppm...
// Needs @tensorflow/tfjs-core, -converter and -backend-wasm 4.22.0 installed outside the
// repository, found through NODE_PATH (scripts/pose-parity.sh does both).
'use strict';
const fs = require('fs');
const path = require('path');
const { tf, readPpm, loadWasmModel } = require('./tfjs-model.js');

async function main() {
  const [modelDir, out, ...inputs] = process.argv.slice(2);
  if (!modelDir || !out || inputs.length === 0) {
    console.error('usage: node scripts/pose-reference.js MODEL_DIR OUT.tsv INPUT.ppm...');
    process.exit(2);
  }
  const model = await loadWasmModel(modelDir, 'movenet-lightning');
  const lines = ['# MoveNet keypoints from TensorFlow.js (WASM backend, one thread) for the ' +
                 '192x192 network input of each frame: y x score per keypoint, y and x in 0..1',
                 '# made by scripts/pose-parity.sh'];
  for (const file of inputs) {
    const ppm = readPpm(file);
    const img = { w: ppm.w, h: ppm.h, data: Int32Array.from(ppm.pixels) };
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
