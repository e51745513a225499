// npm run gen:appearance: rewrite src/model/appearance.generated.json from ../shared.
import { writeFileSync } from 'node:fs';
import { extractAppearance, extractFile } from './extractAppearance.mjs';

writeFileSync(extractFile, extractAppearance());
console.log(`wrote ${extractFile}`);
