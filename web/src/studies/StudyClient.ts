// Every study call of the REST API (docs/studies.md), on the app's RestClient.
import type { RestClient } from '../api/RestClient';
import type { StudyBands, StudyCreate, StudyInfo, StudyTable } from './studyTypes';

type Caller = Pick<RestClient, 'call'>;

export class StudyClient {
    constructor(private readonly rest: Caller) {}

    submit(request: StudyCreate): Promise<{ id: number; runs_total: number }> {
        return this.rest.call('POST', '/studies', request);
    }
    /** The caller's studies, newest first. */
    async list(): Promise<StudyInfo[]> {
        return (await this.rest.call<{ studies: StudyInfo[] }>('GET', '/studies')).studies;
    }
    get(id: number): Promise<StudyInfo> { return this.rest.call('GET', `/studies/${id}`); }
    /** Cancels a queued or running study (a finished one would be deleted: not offered here). */
    cancel(id: number): Promise<unknown> { return this.rest.call('DELETE', `/studies/${id}`); }
    /** Deletes a finished study with its runs. */
    remove(id: number): Promise<unknown> { return this.rest.call('DELETE', `/studies/${id}`); }
    resume(id: number): Promise<StudyInfo> { return this.rest.call('POST', `/studies/${id}/resume`); }
    table(id: number): Promise<StudyTable> { return this.rest.call('GET', `/studies/${id}/results?format=json`); }
    /** The server's CSV (%.17g numbers), byte for byte what scripts get. */
    tableCsv(id: number): Promise<string> {
        return this.rest.call('GET', `/studies/${id}/results?format=csv`, undefined, undefined, 'text/csv');
    }
    bands(id: number): Promise<StudyBands> { return this.rest.call('GET', `/studies/${id}/bands?format=json`); }
}
