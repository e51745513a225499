// The Hopsan GUI layout facts the app needs at run time (display name, library folder, icon
// size, port positions, whether the graphic stays upright), extracted from
// ../shared/reference/appearance.json. The app cannot read ../shared (the Docker image has no
// copy), so the extract is committed; a unit test fails when it is stale.
import { existsSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

export const sourceFile = fileURLToPath(new URL('../../../shared/reference/appearance.json', import.meta.url));
export const extractFile = fileURLToPath(new URL('../src/model/appearance.generated.json', import.meta.url));

export function extractAppearance() {
    if (!existsSync(sourceFile)) throw new Error(`appearance facts not found at ${sourceFile} (../shared is missing)`);
    const facts = JSON.parse(readFileSync(sourceFile, 'utf8'));
    const types = {};
    const take = (key, t, library) => {
        types[key] = {
            displayName: t.displayName || key,
            library,
            width: t.icon?.width ?? 40,
            height: t.icon?.height ?? 40,
            ports: Object.fromEntries(Object.entries(t.ports ?? {}).map(([name, p]) => [name, [p.x, p.y, p.a]])),
        };
        // Hopsan turns the graphic only when iconRotation is exactly ON; written for the others only
        if (t.iconRotation !== 'ON') types[key].upright = true;
    };
    for (const [key, t] of Object.entries(facts.types)) take(key, t, t.library);
    for (const [key, t] of Object.entries(facts.guiBuiltinTypes)) {
        const visible = /^\(HopsanGUI built-in\) visible\/(.*)$/.exec(t.library);
        if (visible) take(key, t, visible[1]);
    }
    return JSON.stringify({ source: facts.source, types }, null, 0) + '\n';
}
