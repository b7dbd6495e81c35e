// Validates one glTF or GLB file with the Khronos glTF-Validator and prints
// its report as JSON on stdout (issues.numErrors, numWarnings, messages).
//   node validate.js NODE_MODULES_DIR FILE
// The module directory is an argument because the package is installed into
// the build tree (build/<preset>/npm/node_modules), never the source tree.
// Exit status: 0 when the report has no errors, 1 when it has, 2 when the
// file could not be validated at all.
'use strict';
const fs = require('fs');
const path = require('path');

const [modulesDir, file] = process.argv.slice(2);
if (!modulesDir || !file) {
    console.error('usage: node validate.js NODE_MODULES_DIR FILE');
    process.exit(2);
}
const validator = require(path.join(path.resolve(modulesDir), 'gltf-validator'));

let bytes;
try {
    bytes = fs.readFileSync(file);
} catch (error) {
    console.error(`${file}: ${error.message}`);
    process.exit(2);
}

validator.validateBytes(new Uint8Array(bytes), {
    uri: path.basename(file),
    maxIssues: 0, // report every issue
    writeTimestamp: false, // same file, same report
    externalResourceFunction: (uri) => new Promise((resolve, reject) => {
        // External buffers and images resolve beside the validated file.
        fs.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri)), (error, data) => {
            if (error) reject(error.toString());
            else resolve(new Uint8Array(data));
        });
    }),
}).then((report) => {
    console.log(JSON.stringify(report, null, 2));
    process.exit(report.issues.numErrors > 0 ? 1 : 0);
}, (error) => {
    console.error(`${file}: ${error}`);
    process.exit(2);
});
