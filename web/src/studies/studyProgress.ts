// A study's state as the page follows it: the StudyInfo and the rows so far, advanced by each
// event.study.progress (rows finished since the previous event, counts, best, failure reasons).
import { mergeRows } from './studyTable';
import type { StudyInfo, StudyProgressEvent, StudyTable, BestPoint, FailureReason } from './studyTypes';

export interface FollowedStudy { info: StudyInfo; table: StudyTable }

export function applyProgress(study: FollowedStudy, event: StudyProgressEvent): FollowedStudy {
    if (event.study_id !== study.info.id) return study;
    const summary = { ...study.info.summary };
    if (event.best) summary.best = event.best as BestPoint;
    if (event.failure_reasons) summary.failure_reasons = event.failure_reasons as FailureReason[];
    const info: StudyInfo = {
        ...study.info,
        state: event.state as StudyInfo['state'],
        runs_done: event.runs_done, runs_failed: event.runs_failed, runs_total: event.runs_total,
        progress: event.runs_total > 0 ? (event.runs_done + event.runs_failed) / event.runs_total : study.info.progress,
        error: event.error ?? study.info.error,
        summary,
    };
    const rows = event.rows as (number | null)[][];
    return { info, table: rows.length > 0 || event.columns ? mergeRows(study.table, event.columns, rows) : study.table };
}

/** The line under a study's progress bar. */
export function progressText(info: StudyInfo): string {
    const finished = info.runs_done + info.runs_failed;
    const failed = info.runs_failed > 0 ? `, ${info.runs_failed} failed` : '';
    const reason = info.summary.finish_reason ? ` (${info.summary.finish_reason})` : '';
    return `${info.state}${reason}: ${finished} of ${info.runs_total} runs${failed}`;
}
