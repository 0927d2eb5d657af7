// Validate glTF files with the Khronos glTF-Validator; run by scripts/gltf-validate.sh:
//   node scripts/gltf-validate.cjs VALIDATOR_MODULE_DIR FILE...
// CommonJS (not an ES module) so that `require` works on Node 18 as on Node 20.
'use strict';
const fs = require('fs');
const path = require('path');

const SEVERITY = ['error', 'warning', 'info', 'hint'];

async function validateFile(validator, file) {
  let bytes;
  try {
    bytes = new Uint8Array(fs.readFileSync(file));
  } catch (e) {
    console.log(`${file}: cannot read: ${e.message}`);
    return false;
  }
  const dir = path.dirname(file);
  let report;
  try {
    report = await validator.validateBytes(bytes, {
      uri: path.basename(file),
      maxIssues: 0, // no limit
      // Buffers and images the file names by relative URI (a .bin beside a .gltf);
      // data: URIs the validator decodes itself.
      externalResourceFunction: (uri) =>
        fs.promises
          .readFile(path.resolve(dir, decodeURIComponent(uri)))
          .then((b) => new Uint8Array(b)),
    });
  } catch (e) {
    console.log(`${file}: cannot validate: ${e && e.message ? e.message : e}`);
    return false;
  }
  const issues = report.issues;
  console.log(
    `${file}: ${issues.numErrors} errors, ${issues.numWarnings} warnings, ` +
      `${issues.numInfos} infos, ${issues.numHints} hints`,
  );
  for (const m of issues.messages) {
    if (m.severity > 1) continue;
    const where = m.pointer ? ` at ${m.pointer}` : m.offset !== undefined ? ` at byte ${m.offset}` : '';
    console.log(`  ${SEVERITY[m.severity]} ${m.code}: ${m.message}${where}`);
  }
  return issues.numErrors === 0;
}

async function main() {
  const [moduleDir, ...files] = process.argv.slice(2);
  if (!moduleDir || files.length === 0) {
    console.error('usage: node scripts/gltf-validate.cjs VALIDATOR_MODULE_DIR FILE...');
    process.exit(2);
  }
  const validator = require(path.resolve(moduleDir));
  let ok = true;
  for (const file of files) {
    if (!(await validateFile(validator, file))) ok = false;
  }
  process.exitCode = ok ? 0 : 1;
}

main().catch((e) => {
  console.error(`gltf-validate: ${e && e.stack ? e.stack : e}`);
  process.exit(1);
});
