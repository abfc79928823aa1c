// Validates one .glb with the Khronos glTF-Validator (npm package `gltf-validator`) and prints
// its report as JSON on stdout: usage `node gltf_validate.js <gltf-validator dir> <file.glb>`.
"use strict";
const fs = require("fs");
const path = require("path");

const validator = require(path.resolve(process.argv[2]));
const file = process.argv[3];
validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
    uri: path.basename(file), maxIssues: 0, writeTimestamp: false,
}).then((report) => {
    process.stdout.write(JSON.stringify(report));
}, (err) => {
    process.stderr.write(String(err) + "\n");
    process.exit(2);
});
