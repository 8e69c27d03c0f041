// Decodes and encodes Sparkplug B payloads with Eclipse Tahu's sparkplug-payload, one request a line, so that the
// gateway's tests check what it publishes (and send it commands) with an implementation that is not its own.
//   decode <base64>   -> the decoded payload as JSON (64-bit numbers as decimal strings)
//   encode <json>     -> the payload encoded, as base64
'use strict';
const readline = require('readline');
const sparkplug = require('sparkplug-payload').get('spBv1.0');
const Long = require('long');

function plain(value) {
  if (Long.isLong(value)) return value.toString();
  if (typeof value === 'bigint') return value.toString();
  if (value instanceof Uint8Array) return Buffer.from(value).toString('base64');
  if (Array.isArray(value)) return value.map(plain);
  if (value && typeof value === 'object') {
    const out = {};
    for (const [k, v] of Object.entries(value)) out[k] = plain(v);
    return out;
  }
  return value;
}

const lines = readline.createInterface({ input: process.stdin });
lines.on('line', (line) => {
  const space = line.indexOf(' ');
  const verb = line.slice(0, space);
  const arg = line.slice(space + 1);
  try {
    if (verb === 'decode') {
      const payload = sparkplug.decodePayload(Buffer.from(arg, 'base64'));
      process.stdout.write(JSON.stringify({ ok: plain(payload) }) + '\n');
    } else if (verb === 'encode') {
      const bytes = sparkplug.encodePayload(JSON.parse(arg));
      process.stdout.write(JSON.stringify({ ok: Buffer.from(bytes).toString('base64') }) + '\n');
    } else {
      process.stdout.write(JSON.stringify({ error: 'unknown verb ' + verb }) + '\n');
    }
  } catch (e) {
    process.stdout.write(JSON.stringify({ error: String(e && e.message || e) }) + '\n');
  }
});
