// The study shapes the browser reads (docs/studies.md). The generated StudyInfo and
// StudyProgressEvent leave summary, best and failure_reasons open; these name their fields.
import type { StudyCreate, StudyInfo as GeneratedStudyInfo, StudyProgressEvent } from '../protocol/generated';

export type { StudyCreate, StudyProgressEvent };
export type StudyKind = StudyCreate['kind'];

/** The best run of a study with an objective. */
export interface BestPoint { run: number; parameters: Record<string, number>; objective: number }

/** Failed runs grouped by their error message, most frequent first. */
export interface FailureReason { message: string; count: number; first_run: number }

export interface StudySummary {
    best?: BestPoint;
    finish_reason?: string;
    failure_reasons?: FailureReason[];
    correlations?: Record<string, Record<string, number>>;
    correlations_n?: number;
    bands_n?: number;
    runs_reused?: number;
}

export type StudyInfo = Omit<GeneratedStudyInfo, 'summary'> & { summary: StudySummary };

/** GET /studies/{id}/results?format=json: one row per finished run, cells as the columns say. */
export interface StudyTable {
    columns: string[];
    rows: (number | null)[][];
    /** The error of each failed run, by run index. */
    errors: Record<string, string>;
}

export interface BandCurves { mean: number[]; sd: number[]; minus_2sd: number[]; minus_1sd: number[]; plus_1sd: number[]; plus_2sd: number[] }

/** GET /studies/{id}/bands: per variable the mean and ±1σ, ±2σ over time, from `n` runs. */
export interface StudyBands { n?: number; time: number[]; variables: Record<string, BandCurves> }

export const FINAL_STATES: ReadonlySet<string> = new Set(['done', 'failed', 'cancelled', 'interrupted', 'dead']);
