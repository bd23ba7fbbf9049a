// A minimal PNG reader for the browser test: 8-bit RGBA, non-interlaced (what a canvas
// exports), decoded with node's zlib and the five PNG row filters (PNG spec, section 9).
// Returns {width, height, pixels} with pixels an RGBA Uint8Array, or throws.

import {inflateSync} from 'node:zlib';

const kSignature = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);

function paeth(a, b, c) {
  const p = a + b - c;
  const pa = Math.abs(p - a);
  const pb = Math.abs(p - b);
  const pc = Math.abs(p - c);
  if (pa <= pb && pa <= pc) return a;
  return pb <= pc ? b : c;
}

export function readPng(bytes) {
  if (!bytes.subarray(0, 8).equals(kSignature)) throw new Error('not a PNG file');
  let offset = 8;
  let header = null;
  const data = [];
  while (offset < bytes.length) {
    const length = bytes.readUInt32BE(offset);
    const type = bytes.toString('latin1', offset + 4, offset + 8);
    const body = bytes.subarray(offset + 8, offset + 8 + length);
    if (type === 'IHDR') {
      header = {
        width: body.readUInt32BE(0), height: body.readUInt32BE(4), bitDepth: body[8],
        colorType: body[9], interlace: body[12],
      };
    } else if (type === 'IDAT') {
      data.push(body);
    } else if (type === 'IEND') {
      break;
    }
    offset += 12 + length;
  }
  if (!header) throw new Error('PNG without IHDR');
  if (header.bitDepth !== 8 || header.colorType !== 6 || header.interlace !== 0) {
    throw new Error(`expected 8-bit RGBA non-interlaced, got depth ${header.bitDepth} color type ${header.colorType}`);
  }
  const raw = inflateSync(Buffer.concat(data));
  const {width, height} = header;
  const stride = width * 4;
  if (raw.length !== height * (stride + 1)) throw new Error('PNG data has the wrong length');
  const pixels = new Uint8Array(height * stride);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)];
    const row = raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1));
    const out = y * stride;
    const prior = (y - 1) * stride;
    for (let x = 0; x < stride; ++x) {
      const a = x >= 4 ? pixels[out + x - 4] : 0;
      const b = y > 0 ? pixels[prior + x] : 0;
      const c = x >= 4 && y > 0 ? pixels[prior + x - 4] : 0;
      let predictor;
      switch (filter) {
        case 0: predictor = 0; break;
        case 1: predictor = a; break;
        case 2: predictor = b; break;
        case 3: predictor = (a + b) >> 1; break;
        case 4: predictor = paeth(a, b, c); break;
        default: throw new Error(`unknown PNG filter ${filter}`);
      }
      pixels[out + x] = (row[x] + predictor) & 0xff;
    }
  }
  return {width, height, pixels};
}
