// SPDX-License-Identifier: Apache-2.0
// node gltf_validate.js FILE...: Khronos's glTF-Validator (npm gltf-validator, found through
// NODE_PATH) on each file (.glb, or .gltf with its external buffers and images beside it). Per
// file it prints "validator VERSION errors E warnings W infos I", then "error codes: CODE ..."
// (each error's code once, sorted), then each error or warning as "CODE POINTER: MESSAGE"; with
// several files each block starts with "== FILE". Exit status 0 when no file has an error.
const fs = require('fs'), path = require('path'), validator = require('gltf-validator');
const files = process.argv.slice(2);
const check = (file) => {
  const external = (uri) => new Promise((resolve, reject) => {
    try { resolve(new Uint8Array(fs.readFileSync(path.resolve(path.dirname(file), decodeURIComponent(uri))))); }
    catch (e) { reject(e.toString()); }
  });
  return validator.validateBytes(new Uint8Array(fs.readFileSync(file)),
                                 {maxIssues: 200, uri: file, externalResourceFunction: external});
};
(async () => {
  let failed = false;
  for (const file of files) {
    if (files.length > 1) console.log(`== ${file}`);
    const r = await check(file), i = r.issues;
    const codes = [...new Set(i.messages.filter(m => m.severity === 0).map(m => m.code))].sort();
    console.log(`validator ${r.validatorVersion} errors ${i.numErrors} warnings ${i.numWarnings} infos ${i.numInfos}`);
    console.log(`error codes: ${codes.join(' ')}`);
    for (const m of i.messages) if (m.severity <= 1) console.log(`${m.code} ${m.pointer || ''}: ${m.message}`);
    failed = failed || i.numErrors > 0;
  }
  process.exit(failed ? 1 : 0);
})().catch(e => { console.error(`validator failed: ${e}`); process.exit(2); });
