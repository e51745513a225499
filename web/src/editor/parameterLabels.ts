// How a component's parameters read in the panel: the description as the label, the short
// name beside it ("y_A", not "y_A#Value"), and the start values of its ports' nodes
// ("P1#HeatFlow") apart from the parameters proper.
import type { Param } from '../protocol/types';

/** An input's own value is "name#Value"; any other "Port#Variable" is a node's start value. */
export function isStartValue(p: Param): boolean {
    const hash = p.name.indexOf('#');
    return hash > 0 && p.name.slice(hash + 1) !== 'Value';
}

export function splitParameters(params: Param[]): { parameters: Param[]; startValues: Param[] } {
    return { parameters: params.filter((p) => !isStartValue(p)), startValues: params.filter(isStartValue) };
}

/** The short name a user types in expressions and sees in Hopsan: without "#Value". */
export function shortName(p: Param): string {
    return p.name.replace(/#Value$/, '');
}

/** "HeatFlow" -> "Heat flow". */
function words(camel: string): string {
    const spaced = camel.replace(/([a-z])([A-Z])/g, '$1 $2').toLowerCase();
    return spaced.charAt(0).toUpperCase() + spaced.slice(1);
}

/** The label: the description when there is one; for a start value "P1: Heat flow". */
export function parameterLabel(p: Param): string {
    if (isStartValue(p)) {
        const [port, variable] = p.name.split('#');
        return `${port}: ${words(variable)}`;
    }
    return p.description.trim() || shortName(p);
}
