// Runs the Khronos glTF validator (npm gltf-validator, installed by scripts/install-gltf-validator)
// on glTF files and checks its errors against what is expected of each file: none, unless an
// expectations file (JSON: file name -> list of error codes) lists the codes of the defect the
// file carries on purpose; then exactly those codes and no others. Warnings are printed, not
// counted. Exits 1 if any file differs from its expectation.
//
// Usage: node scripts/validate-gltf.mjs [--expect EXPECTED.json] FILE...
import { createRequire } from "node:module";
import fs from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";

const repository = path.dirname(path.dirname(fileURLToPath(import.meta.url)));
const require = createRequire(path.join(repository, "build-tools/gltf-validator/package.json"));
const validator = require("gltf-validator");
const kError = 0;

const args = process.argv.slice(2);
let expectations = {};
if (args[0] === "--expect") {
    expectations = JSON.parse(fs.readFileSync(args[1], "utf8"));
    args.splice(0, 2);
}

async function validate(file) {
    const report = await validator.validateBytes(new Uint8Array(fs.readFileSync(file)), {
        uri: path.basename(file),
        maxIssues: 0,
        externalResourceFunction: (uri) =>
            fs.promises.readFile(path.resolve(path.dirname(file), decodeURIComponent(uri))),
    });
    const errors = report.issues.messages.filter((m) => m.severity === kError);
    const codes = [...new Set(errors.map((m) => m.code))].sort();
    const expected = [...(expectations[path.basename(file)] || [])].sort();
    const ok = JSON.stringify(codes) === JSON.stringify(expected);
    const warnings = report.issues.numWarnings;
    const what = expected.length ? `only the intended ${expected.join(", ")}` : "0 errors";
    console.log(`${ok ? "ok  " : "FAIL"} ${file}: ${ok ? what : `expected ${what}`}` +
                (warnings ? `, ${warnings} warning(s)` : ""));
    if (!ok)
        for (const m of errors) console.log(`       ${m.code} at ${m.pointer || "/"}: ${m.message}`);
    return ok;
}

let failures = 0;
for (const file of args) {
    try {
        if (!(await validate(file))) ++failures;
    } catch (error) {
        console.log(`FAIL ${file}: the validator could not run: ${String(error).split("\n")[0]}`);
        ++failures;
    }
}
console.log(`validate-gltf: ${args.length - failures} of ${args.length} files as expected`);
process.exit(failures ? 1 : 0);
