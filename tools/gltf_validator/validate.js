// validate.js FILE... - run the Khronos glTF validator on glTF files and
// print one line per file: "FILE: E errors, W warnings, I infos, H hints",
// then each error and warning ("  ERROR CODE at POINTER: message").
// Exit status: 0 when no file has an error or a warning, 1 otherwise, 2 when
// a file cannot be read or validated at all. Used by the tests of
// scene.glb; the validator is installed here by scripts/setup.sh.
'use strict';
const fs = require('fs');
const validator = require('gltf-validator');

const severities = ['ERROR', 'WARNING', 'INFO', 'HINT'];

async function main(files) {
  let status = 0;
  for (const file of files) {
    let report;
    try {
      report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), { uri: file, maxIssues: 1000 });
    } catch (e) {
      console.log(`${file}: cannot validate: ${e}`);
      status = 2;
      continue;
    }
    const i = report.issues;
    console.log(`${file}: ${i.numErrors} errors, ${i.numWarnings} warnings, ${i.numInfos} infos, ${i.numHints} hints`);
    for (const m of i.messages)
      if (m.severity <= 1) console.log(`  ${severities[m.severity]} ${m.code} at ${m.pointer || m.offset}: ${m.message}`);
    if (i.numErrors > 0 || i.numWarnings > 0) status = Math.max(status, 1);
  }
  return status;
}

main(process.argv.slice(2)).then((status) => process.exit(status));
