// node gltf_validate.js FILE.glb: Khronos's glTF-Validator (npm gltf-validator, found through
// NODE_PATH) on one file. Prints "validator VERSION errors E warnings W infos I" and each
// error or warning as "CODE POINTER: MESSAGE"; exit status 0 when there is no error.
const fs = require('fs'), validator = require('gltf-validator');
validator.validateBytes(new Uint8Array(fs.readFileSync(process.argv[2])), {maxIssues: 200}).then(r => {
  const i = r.issues;
  console.log(`validator ${r.validatorVersion} errors ${i.numErrors} warnings ${i.numWarnings} infos ${i.numInfos}`);
  for (const m of i.messages) if (m.severity <= 1) console.log(`${m.code} ${m.pointer || ''}: ${m.message}`);
  process.exit(i.numErrors === 0 ? 0 : 1);
}, e => { console.error(`validator failed: ${e}`); process.exit(2); });
