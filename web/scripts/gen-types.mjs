// npm run gen:types: regenerate src/protocol/generated.ts from protocol/*.schema.json.
import { writeFileSync } from 'node:fs';
import { generateTypes, generatedFile } from './generateTypes.mjs';

writeFileSync(generatedFile, await generateTypes());
console.log(`wrote ${generatedFile}`);
