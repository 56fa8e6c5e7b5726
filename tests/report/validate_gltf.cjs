// Runs the Khronos glTF-Validator (npm package gltf-validator) on GLB files; exit status 1 on any error or
// warning. Usage: NODE_PATH=DIR/node_modules node validate_gltf.cjs FILE.glb...
'use strict';
const fs = require('fs');
const validator = require('gltf-validator');

const severities = ['error', 'warning', 'info', 'hint'];

(async () => {
  let failed = false;
  for (const path of process.argv.slice(2)) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(path)), {maxIssues: 50});
    const issues = report.issues;
    console.log(`${path}: glTF-Validator ${report.validatorVersion}: ${issues.numErrors} errors, ` +
                `${issues.numWarnings} warnings, ${issues.numInfos} infos, ${issues.numHints} hints`);
    for (const m of issues.messages)
      console.log(`  ${severities[m.severity] || m.severity} ${m.code} ${m.pointer || ''}: ${m.message}`);
    if (issues.numErrors > 0 || issues.numWarnings > 0) failed = true;
  }
  process.exit(failed ? 1 : 0);
})().catch((e) => {
  console.error(`validate_gltf: ${e && e.message ? e.message : e}`);
  process.exit(1);
});
