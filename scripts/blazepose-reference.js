// Reference landmarks from TensorFlow.js for the BlazePose parity test: runs the same BlazePose
// graph model on 256x256 RGB inputs (binary PPM files written by the blazepose_inputs tool),
// scaled to 0..1 as tfjs-models' blazepose_tfjs does, with the WASM backend on one thread,
// offline. Per input: the person flag, then for each of the 33 body landmarks x y (input
// pixels) and the world landmark's x y z (metres, the crop's axes).
//   node scripts/blazepose-reference.js MODEL_DIR OUT.tsv INPUT.ppm...
// Needs @tensorflow/tfjs-core, -converter and -backend-wasm 4.22.0 installed outside the
// repository, found through NODE_PATH (scripts/pose-parity.sh does both).
'use strict';
const fs = require('fs');
const path = require('path');
const { tf, readPpm, loadWasmModel } = require('./tfjs-model.js');

async function main() {
  const [modelDir, out, ...inputs] = process.argv.slice(2);
  if (!modelDir || !out || inputs.length === 0) {
    console.error('usage: node scripts/blazepose-reference.js MODEL_DIR OUT.tsv INPUT.ppm...');
    process.exit(2);
  }
  const model = await loadWasmModel(modelDir, 'blazepose-full');
  const lines = ['# BlazePose full landmarks from TensorFlow.js (WASM backend, one thread) for the ' +
                 '256x256 network input of each frame (input scaled to 0..1): person flag, then ' +
                 'per body landmark x y (input pixels) and world x y z (metres, crop axes)',
                 '# made by scripts/pose-parity.sh'];
  for (const file of inputs) {
    const ppm = readPpm(file);
    const img = { w: ppm.w, h: ppm.h, data: Float32Array.from(ppm.pixels, (v) => v / 255) };
    const [ld, world, flag] = tf.tidy(() => model.execute(
        tf.tensor4d(img.data, [1, img.h, img.w, 3], 'float32'),
        ['Identity_2', 'Identity_4', 'Identity_3']));
    const l = await ld.data(), w = await world.data(), f = await flag.data();
    tf.dispose([ld, world, flag]);
    const values = [f[0].toFixed(6)];
    for (let i = 0; i < 33; ++i) {
      values.push(l[5 * i].toFixed(4), l[5 * i + 1].toFixed(4));
      values.push(w[3 * i].toFixed(6), w[3 * i + 1].toFixed(6), w[3 * i + 2].toFixed(6));
    }
    lines.push([path.basename(file, '.ppm'), ...values].join('\t'));
  }
  fs.writeFileSync(out, lines.join('\n') + '\n');
}

main().catch((e) => {
  console.error(e.message || e);
  process.exit(1);
});
