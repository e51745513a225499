// Imported first by main.ts: the app's storage works even where the browser refuses it (a
// learning platform's frame, see storageFallback.ts).
import { useMemoryStorageWhereRefused } from './storageFallback';

useMemoryStorageWhereRefused();
