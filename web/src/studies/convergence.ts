// An optimisation's convergence: the objective of each run and the best so far, by run.
import type { StudyTable } from './studyTypes';

export type Goal = 'minimise' | 'maximise';

export interface ConvergenceSeries { runs: number[]; objective: (number | null)[]; best: (number | null)[] }

/** The runs in run order with their objective and the best so far (failed runs: null, the best carries on). */
export function convergenceSeries(table: StudyTable, goal: Goal): ConvergenceSeries | null {
    const runAt = table.columns.indexOf('run');
    const objAt = table.columns.indexOf('objective');
    if (runAt < 0 || objAt < 0) return null;
    const rows = [...table.rows].sort((a, b) => Number(a[runAt]) - Number(b[runAt]));
    const better = (a: number, b: number) => (goal === 'minimise' ? a < b : a > b);
    let best: number | null = null;
    const series: ConvergenceSeries = { runs: [], objective: [], best: [] };
    for (const r of rows) {
        const value = r[objAt];
        const finite = typeof value === 'number' && Number.isFinite(value) ? value : null;
        if (finite !== null && (best === null || better(finite, best))) best = finite;
        series.runs.push(Number(r[runAt]));
        series.objective.push(finite);
        series.best.push(best);
    }
    return series;
}

/**
 * The goal of a study whose request the page does not hold (listed after a reload): the best
 * point's objective is the lowest of the table's for minimise, else the highest.
 */
export function inferGoal(table: StudyTable, bestObjective: number | undefined): Goal {
    const objAt = table.columns.indexOf('objective');
    const values = table.rows.map((r) => r[objAt]).filter((v): v is number => typeof v === 'number' && Number.isFinite(v));
    if (bestObjective === undefined || values.length === 0) return 'minimise';
    return bestObjective <= Math.min(...values) ? 'minimise' : 'maximise';
}
