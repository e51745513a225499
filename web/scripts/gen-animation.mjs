// npm run gen:animation: rewrite src/animation/animation.generated.json from ../shared.
import { writeFileSync } from 'node:fs';
import { extractAnimation, extractFile } from './extractAnimation.mjs';

writeFileSync(extractFile, extractAnimation());
console.log(`wrote ${extractFile}`);
