/** The demo's surfaces by their names in the panel and in messages, and which of them are ACC schemes. */
import { ACC_SURFACES, type DemoParams } from './params.ts';

/** The surfaces by their names in the panel and in messages. */
export const SURFACE_NAMES: Record<DemoParams['surface'], string> = {
  'catmull-clark': 'Catmull-Clark',
  phong: 'Phong',
  'bezier-acc': 'Bezier ACC',
  'gregory-acc': 'Gregory ACC',
  'pm-acc': 'Pm ACC',
  cage: 'flat cage',
};

/** An ACC scheme (the surfaces the error views measure). */
export function isAcc(surface: string | null | undefined): surface is (typeof ACC_SURFACES)[number] {
  return (ACC_SURFACES as readonly string[]).includes(surface ?? '');
}
