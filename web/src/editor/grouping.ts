// Group components into a new subsystem by rewriting the model's .hmf: the protocol has no
// request to move components into a subsystem, so the app edits the saved file and reopens it.
// Connections that cross the new boundary go through new system ports.

export interface Grouped { hmf: string; subsystemName: string }

function childrenNamed(parent: Element, tag: string): Element[] {
    return Array.from(parent.children).filter((c) => c.tagName === tag);
}

function child(parent: Element, tag: string): Element | null {
    return childrenNamed(parent, tag)[0] ?? null;
}

function ensureChild(doc: Document, parent: Element, tag: string): Element {
    return child(parent, tag) ?? parent.appendChild(doc.createElement(tag));
}

function systemElement(doc: Document, path: string[]): Element {
    let sys = doc.documentElement.tagName === 'hopsanmodelfile' ? child(doc.documentElement, 'system') : null;
    if (!sys) throw new Error('not a Hopsan model file');
    for (const name of path) {
        const objects = child(sys, 'objects');
        const next: Element | undefined = objects ? childrenNamed(objects, 'system').find((s) => s.getAttribute('name') === name) : undefined;
        if (!next) throw new Error(`no subsystem ${name} in the saved model`);
        sys = next;
    }
    return sys;
}

function poseOf(el: Element): { x: number; y: number } {
    const pose = child(child(el, 'hopsangui') ?? el, 'pose');
    return { x: Number(pose?.getAttribute('x') ?? 0), y: Number(pose?.getAttribute('y') ?? 0) };
}

function makePose(doc: Document, x: number, y: number): Element {
    const gui = doc.createElement('hopsangui');
    const pose = doc.createElement('pose');
    pose.setAttribute('x', String(x));
    pose.setAttribute('y', String(y));
    pose.setAttribute('a', '0');
    pose.setAttribute('flipped', 'false');
    gui.appendChild(pose);
    return gui;
}

function uniqueIn(taken: Set<string>, wanted: string): string {
    let name = wanted;
    for (let i = 1; taken.has(name); ++i) name = `${wanted}_${i}`;
    taken.add(name);
    return name;
}

export function groupIntoSubsystem(hmf: string, path: string[], names: string[]): Grouped {
    const doc = new DOMParser().parseFromString(hmf, 'application/xml');
    if (doc.getElementsByTagName('parsererror').length > 0) throw new Error('the saved model is not valid XML');
    const sys = systemElement(doc, path);
    const objects = ensureChild(doc, sys, 'objects');
    const connections = ensureChild(doc, sys, 'connections');
    const chosen = new Set(names);
    const moved = Array.from(objects.children).filter((e) => (e.tagName === 'component' || e.tagName === 'system') && chosen.has(e.getAttribute('name') ?? ''));
    if (moved.length === 0) throw new Error('none of the selected components is in the saved model');

    const outerNames = new Set(Array.from(objects.children).map((e) => e.getAttribute('name') ?? ''));
    const subName = uniqueIn(outerNames, 'Subsystem');
    const centre = moved.map(poseOf).reduce((a, p) => ({ x: a.x + p.x / moved.length, y: a.y + p.y / moved.length }), { x: 0, y: 0 });

    const sub = doc.createElement('system');
    sub.setAttribute('typename', 'Subsystem');
    sub.setAttribute('name', subName);
    const time = doc.createElement('simulationtime');
    time.setAttribute('inherit_timestep', 'true');
    time.setAttribute('timestep', child(sys, 'simulationtime')?.getAttribute('timestep') ?? '0.001');
    sub.appendChild(time);
    sub.appendChild(doc.createElement('parameters'));
    sub.appendChild(makePose(doc, Math.round(centre.x), Math.round(centre.y)));
    const subObjects = sub.appendChild(doc.createElement('objects'));
    const subConnections = sub.appendChild(doc.createElement('connections'));
    for (const el of moved) subObjects.appendChild(el);

    const innerNames = new Set(names);
    const portFor = new Map<string, string>();
    for (const conn of childrenNamed(connections, 'connect')) {
        const a = conn.getAttribute('startcomponent') ?? '';
        const b = conn.getAttribute('endcomponent') ?? '';
        const aIn = chosen.has(a);
        const bIn = chosen.has(b);
        if (aIn && bIn) {
            subConnections.appendChild(conn);
            continue;
        }
        if (!aIn && !bIn) continue;
        // a cut connection: inner end -> new system port; outer end -> the subsystem's port
        const innerSide = aIn ? 'start' : 'end';
        const innerComp = conn.getAttribute(`${innerSide}component`)!;
        const innerPort = conn.getAttribute(`${innerSide}port`)!;
        const key = `${innerComp}.${innerPort}`;
        let spName = portFor.get(key);
        if (!spName) {
            spName = uniqueIn(innerNames, `${innerComp}_${innerPort}`);
            portFor.set(key, spName);
            const coords = Array.from(conn.getElementsByTagName('coordinate'));
            const outerPoint = coords.length ? (aIn ? coords[coords.length - 1] : coords[0]) : null;
            const sp = doc.createElement('systemport');
            sp.setAttribute('name', spName);
            sp.setAttribute('typename', 'HopsanGUIContainerPort');
            sp.appendChild(makePose(doc, Number(outerPoint?.getAttribute('x') ?? centre.x), Number(outerPoint?.getAttribute('y') ?? centre.y)));
            subObjects.insertBefore(sp, subObjects.firstChild);
            const inner = doc.createElement('connect');
            inner.setAttribute('startcomponent', innerComp);
            inner.setAttribute('startport', innerPort);
            inner.setAttribute('endcomponent', spName);
            inner.setAttribute('endport', spName);
            subConnections.appendChild(inner);
        }
        conn.setAttribute(`${innerSide}component`, subName);
        conn.setAttribute(`${innerSide}port`, spName);
        // the old line no longer fits: the editor draws a fresh one
        const gui = child(conn, 'hopsangui');
        if (gui) conn.removeChild(gui);
    }
    objects.appendChild(sub);
    return { hmf: new XMLSerializer().serializeToString(doc), subsystemName: subName };
}
