// The address of an open model: #/model/<id>[?assignment=<aid>][&path=Sub/Inner]. The path is
// the subsystem on screen, so Back and Forward move through subsystems inside the editor and a
// reload opens the same level.
export interface ModelRoute { id: number; assignment?: number; path: string[] }

export function parseModelRoute(hash: string): ModelRoute | null {
    const match = /^#\/model\/(\d+)(?:\?(.*))?$/.exec(hash);
    if (!match) return null;
    const query = new URLSearchParams(match[2] ?? '');
    const assignment = query.get('assignment');
    if (assignment !== null && !/^\d+$/.test(assignment)) return null;
    const path = query.get('path');
    return {
        id: Number(match[1]),
        ...(assignment !== null ? { assignment: Number(assignment) } : {}),
        path: path ? path.split('/').filter((name) => name !== '') : [],
    };
}

export function modelRouteHash(route: ModelRoute): string {
    const query: string[] = [];
    if (route.assignment !== undefined) query.push(`assignment=${route.assignment}`);
    // subsystem names are letters, digits and underscores (sanitizeName); encoded all the same
    if (route.path.length > 0) query.push(`path=${route.path.map(encodeURIComponent).join('/')}`);
    return `#/model/${route.id}${query.length > 0 ? `?${query.join('&')}` : ''}`;
}

/** Whether two addresses show the same model (perhaps at different levels). */
export function sameModel(a: ModelRoute | null, b: ModelRoute | null): boolean {
    return a !== null && b !== null && a.id === b.id && a.assignment === b.assignment;
}
