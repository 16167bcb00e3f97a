/**
 * One request to a fresh worker, and its answer: the way the page hands a large file's parse
 * (src/app/parse-off-thread.ts) and a large cage's preparation (src/app/cc-tables.ts) off its
 * thread. The worker is made by the caller (`start`: Vite bundles a worker only from a
 * `new Worker(new URL('./file.ts', import.meta.url))` written where it is used) and ends with
 * its answer or its error, so none outlives the request.
 */

/** What one message from the worker means: `read` returns the result, throws (the request
 * failed, with that error), or returns undefined (a progress message: wait for the next). */
export function runWorkerOnce<Reply, T>(
  start: () => Worker,
  request: unknown,
  read: (reply: Reply) => T | undefined,
  stopped: (message: string) => Error,
): Promise<T> {
  return new Promise((resolve, reject) => {
    const worker = start();
    worker.onmessage = (e: MessageEvent<Reply>) => {
      let result: T | undefined;
      try {
        result = read(e.data);
      } catch (error) {
        worker.terminate();
        reject(error);
        return;
      }
      if (result === undefined) return;
      worker.terminate();
      resolve(result);
    };
    worker.onerror = (e) => {
      worker.terminate();
      reject(stopped(e.message));
    };
    worker.postMessage(request);
  });
}
