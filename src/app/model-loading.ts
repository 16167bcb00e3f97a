/**
 * The load flow's file work: one of the project's models fetched with its height map, and a
 * user's PNG read as a height map for the shown model. What is shown then, and when, is the
 * controller's (src/app/controller.ts); the demo hands the results to it
 * (src/app/tessellation-demo.ts).
 */
import { uvCoverage } from '../mesh/index.ts';
import type { Cage } from '../mesh/types.ts';
import { builtinHeight, decodeHeightImage, defaultHeightScale, fetchBuiltinHeight, type HeightEntry } from './displacement.ts';
import { checkFileSize, MAX_HEIGHT_MAP_FILE_BYTES } from './file-size.ts';
import { loadModelFromUrl, modelUrl, type LoadedModel } from './models.ts';
import { showToast } from './ui.ts';

/** The project's model `name`, its height map (if it has one) put in `heights` before it is
 * returned, so the first upload already displaces. A height map that fails is said, not fatal. */
export async function fetchBuiltinModel(name: string, heights: WeakMap<Cage, HeightEntry>): Promise<LoadedModel> {
  const dir = modelUrl(name).replace(/[^/]*$/, '');
  const fetchHeight = async () => {
    const d = await builtinHeight(name, dir);
    return d ? fetchBuiltinHeight(d, dir) : null;
  };
  const [model, height] = await Promise.all([loadModelFromUrl(modelUrl(name), name), fetchHeight().catch((e: Error) => e)]);
  if (height instanceof Error)
    showToast(`${height.message}\n\nShowing ${name} undisplaced.`, { kind: 'info', title: 'No height map', timeout: 8000 });
  else if (height) heights.set(model.cage, height);
  return model;
}

/** `file` decoded as a height map for `model`, which needs uvs on every face corner; throws an
 * Error whose message says why it cannot be used (a file over the size cap is not read). */
export async function readHeightMap(file: Blob & { name: string }, model: LoadedModel): Promise<HeightEntry['height']['map']> {
  checkFileSize(file, MAX_HEIGHT_MAP_FILE_BYTES, 'height maps');
  if (uvCoverage(model.cage) !== 'complete')
    throw new Error(`${model.title} has no texture coordinates on every face corner (OBJ vt and f v/vt): a height map needs them.`);
  return decodeHeightImage(file, file.name);
}

/** The entry of a user's map on `model`: the scale and mid level of the map it replaces, if any. */
export function userHeightEntry(map: HeightEntry['height']['map'], source: string, model: LoadedModel, before?: HeightEntry): HeightEntry {
  return {
    height: { map, wrap: 'repeat' },
    scale: before?.scale ?? defaultHeightScale(model.cage.positions),
    midLevel: before?.midLevel ?? 0.5,
    source,
  };
}
