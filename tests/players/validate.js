// Validates a Lottie file against the Lottie community's schema (the
// pinned @lottie-animation-community/lottie-specs in this folder).
//   node validate.js ANIM.json
// Prints the errors and warnings (unknown properties) found; exits 1 on
// any error.
'use strict';
const fs = require('fs');
const Ajv2020 = require('ajv/dist/2020');
const { LottieValidator, get_schema_path } = require('@lottie-animation-community/lottie-specs/src/validator-node.js');

const file = process.argv[2];
if (!file) {
    console.error('usage: node validate.js ANIM.json');
    process.exit(2);
}
const schema = JSON.parse(fs.readFileSync(get_schema_path(), 'utf8'));
const validator = new LottieValidator(Ajv2020, schema);
const data = JSON.parse(fs.readFileSync(file, 'utf8'));
const found = validator.validate(data, true);
const errors = found.filter((e) => e.type === 'error');
const warnings = found.filter((e) => e.type !== 'error');
for (const e of found.slice(0, 40)) console.log(`${e.type}: ${e.path || '(top)'}: ${e.message}`);
console.log(`${file}: ${data.layers.length} layers; schema ${schema.$version || schema.$id}: ` +
            `${errors.length} errors, ${warnings.length} warnings`);
process.exit(errors.length ? 1 : 0);
