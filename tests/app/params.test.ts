import { describe, expect, it } from 'vitest';
import { DEFAULT_PARAMS, ERR_RANGE, FACTOR_RANGE, formatParams, isModelUrl, LOD_RANGE, parseParams } from '../../src/app/params.ts';

describe('URL parameters', () => {
  it('an empty query gives the defaults', () => {
    expect(parseParams('')).toEqual(DEFAULT_PARAMS);
    expect(parseParams('?')).toEqual(DEFAULT_PARAMS);
  });

  it('reads every tunable', () => {
    const p = parseParams(
      '?model=torus&mode=fixed&lod=2.5&factor=12&wire=0&cage=1&spin=1&t=1.5&up=z&yaw=30&pitch=-10&dist=3&ui=0&cap=0.5&surface=cage&tessellator=instanced&level=16&split=1&instsurface=gregory-acc&flatshade=1&errorview=normal&errrange=2&compare=pm-acc&disp=0&dscale=2.5&seams=1&material=metal',
    );
    expect(p).toEqual({
      model: 'torus',
      up: 'z',
      mode: 'fixed',
      surface: 'cage',
      patches: false,
      material: 'metal',
      flat: true,
      lod: 2.5,
      factor: 12,
      wire: false,
      cage: true,
      spin: true,
      t: 1.5,
      yaw: 30,
      pitch: -10,
      dist: 3,
      ui: false,
      capacity: 0.5,
      tessellator: 'instanced',
      level: 16,
      split: true,
      instSurface: 'gregory-acc',
      flatShade: true,
      errorView: 'normal',
      errRange: 2,
      compare: 'pm-acc',
      disp: false,
      dscale: 2.5,
      seams: true,
    });
  });

  it('reads the material (clay by default, unknown names ignored) and writes it back', () => {
    expect(DEFAULT_PARAMS.material).toBe('clay');
    expect(parseParams('material=gold').material).toBe('clay');
    expect(formatParams(parseParams('material=METAL'))).toBe('?material=metal');
    expect(formatParams(parseParams('material=clay'))).toBe('');
  });

  it('reads the displacement settings: on by default, scale clamped to [-4, 4], the seam view; and writes them back', () => {
    expect(DEFAULT_PARAMS.disp).toBe(true);
    expect(parseParams('dscale=100').dscale).toBe(4);
    expect(parseParams('dscale=abc').dscale).toBe(1);
    expect(formatParams(parseParams('disp=0&dscale=0.5&seams=1'))).toBe('?disp=0&dscale=0.5&seams=1');
    expect(formatParams(parseParams('disp=1&dscale=1'))).toBe('');
  });

  it('reads the surface (Catmull-Clark by default; older links\' "tessellated" was Phong), patch colours and the flat baseline', () => {
    expect(DEFAULT_PARAMS.surface).toBe('catmull-clark');
    expect(parseParams('surface=phong').surface).toBe('phong');
    expect(parseParams('surface=Catmull-Clark').surface).toBe('catmull-clark');
    expect(parseParams('surface=cc').surface).toBe('catmull-clark');
    expect(parseParams('surface=tessellated').surface).toBe('phong');
    expect(parseParams('surface=bogus').surface).toBe('catmull-clark');
    expect(parseParams('patches=1').patches).toBe(true);
    expect(parseParams('flat=0').flat).toBe(false);
    expect(formatParams(parseParams('surface=phong&patches=1&flat=0'))).toBe('?surface=phong&patches=1&flat=0');
  });

  it('clamps numbers to their ranges and ignores garbage', () => {
    const p = parseParams('lod=1000&factor=-3&t=abc&mode=weird&wire=maybe&pitch=400&up=x');
    expect(p.lod).toBe(LOD_RANGE.max);
    expect(p.factor).toBe(FACTOR_RANGE.min);
    expect(p.t).toBeNull();
    expect(p.mode).toBe(DEFAULT_PARAMS.mode);
    expect(p.wire).toBe(DEFAULT_PARAMS.wire);
    expect(p.pitch).toBe(89);
    expect(p.up).toBe(DEFAULT_PARAMS.up);
    expect(parseParams('lod=NaN&factor=Infinity').lod).toBe(DEFAULT_PARAMS.lod);
  });

  it('accepts the usual spellings of booleans; a bare key means true', () => {
    for (const v of ['1', 'true', 'yes', 'on', '']) expect(parseParams(`cage=${v}`).cage).toBe(true);
    for (const v of ['0', 'false', 'no', 'off']) expect(parseParams(`wire=${v}`).wire).toBe(false);
    expect(parseParams('cage').cage).toBe(true);
  });

  it('freeze=1 is t=0, and an explicit t wins', () => {
    expect(parseParams('freeze=1').t).toBe(0);
    expect(parseParams('freeze=0').t).toBeNull();
    expect(parseParams('freeze=1&t=2').t).toBe(2);
  });

  it('keeps model URLs intact', () => {
    const p = parseParams(`model=${encodeURIComponent('https://example.com/a b.obj?x=1')}`);
    expect(p.model).toBe('https://example.com/a b.obj?x=1');
    expect(isModelUrl(p.model!)).toBe(true);
    expect(isModelUrl('torus')).toBe(false);
    expect(isModelUrl('creased-box')).toBe(false);
    expect(isModelUrl('models/torus.obj')).toBe(true);
  });

  it('formats only what differs from the defaults, and round-trips', () => {
    expect(formatParams(DEFAULT_PARAMS)).toBe('');
    const cases = [
      '?model=gear&mode=fixed&factor=7.5',
      '?lod=0.25&wire=1&cage=1&surface=cage',
      '?model=sheet&up=z&t=0&yaw=12.5&pitch=20&dist=2.5',
      '?spin=1&ui=0&cap=16',
      '?surface=phong',
      '?patches=1&flat=0',
      '?tessellator=instanced&level=32',
      '?split=1&mode=fixed&level=4',
      '?tessellator=instanced&instsurface=pm-acc',
    ];
    for (const q of cases) {
      const p = parseParams(q);
      expect(parseParams(formatParams(p))).toEqual(p);
    }
    expect(formatParams(parseParams('?mode=fixed&factor=7.5'))).toBe('?mode=fixed&factor=7.5');
  });

  it('reads the tessellator (compute by default) and the instanced level (a power of two in 1..64)', () => {
    expect(DEFAULT_PARAMS.tessellator).toBe('compute');
    expect(parseParams('?tessellator=instanced').tessellator).toBe('instanced');
    expect(parseParams('?tessellator=hull').tessellator).toBe('compute');
    expect(parseParams('?level=16').level).toBe(16);
    expect(parseParams('?level=12').level).toBe(8);
    expect(parseParams('?level=500').level).toBe(64);
    expect(parseParams('?level=0').level).toBe(1);
    expect(parseParams('?level=x').level).toBe(DEFAULT_PARAMS.level);
    expect(parseParams('?instsurface=bezier-acc').instSurface).toBe('bezier-acc');
    expect(parseParams('?instsurface=loop').instSurface).toBe('phong');
  });

  it('reads the ACC error view and its range (off and the default range unless asked; the range clamped)', () => {
    expect(DEFAULT_PARAMS.errorView).toBe('off');
    expect(DEFAULT_PARAMS.errRange).toBeNull();
    expect(parseParams('?errorview=geometry').errorView).toBe('geometry');
    expect(parseParams('?errorview=Normal').errorView).toBe('normal');
    expect(parseParams('?errorview=position').errorView).toBe('geometry');
    expect(parseParams('?errorview=off').errorView).toBe('off');
    expect(parseParams('?errorview=heat').errorView).toBe('off');
    expect(parseParams('?errrange=0.002').errRange).toBe(0.002);
    expect(parseParams('?errrange=2.5').errRange).toBe(2.5);
    expect(parseParams('?errrange=1000').errRange).toBe(ERR_RANGE.max);
    expect(parseParams('?errrange=-1').errRange).toBe(ERR_RANGE.min);
    expect(parseParams('?errrange=x').errRange).toBeNull();
    expect(parseParams('?errrange=').errRange).toBeNull();
  });

  it('reads the comparison surface (a tessellated surface, or off)', () => {
    expect(DEFAULT_PARAMS.compare).toBeNull();
    expect(parseParams('?compare=gregory-acc').compare).toBe('gregory-acc');
    expect(parseParams('?compare=PM-ACC').compare).toBe('pm-acc');
    expect(parseParams('?compare=cc').compare).toBe('catmull-clark');
    expect(parseParams('?compare=phong').compare).toBe('phong');
    expect(parseParams('?compare=cage').compare).toBeNull();
    expect(parseParams('?compare=off').compare).toBeNull();
    expect(parseParams('?compare=loop').compare).toBeNull();
  });

  it('writes the error view, its range and the comparison back, and reads them again', () => {
    const p = parseParams('?surface=bezier-acc&errorview=normal&errrange=3&compare=gregory-acc');
    const q = formatParams(p);
    expect(q).toContain('errorview=normal');
    expect(q).toContain('errrange=3');
    expect(q).toContain('compare=gregory-acc');
    expect(parseParams(q)).toEqual(p);
    expect(formatParams(DEFAULT_PARAMS)).toBe('');
    expect(formatParams({ ...DEFAULT_PARAMS, errRange: 1e-4 })).toBe('?errrange=0.0001');
  });
});

describe('the model list', () => {
  it("names exactly the project's models in public/models (the page asks the server for no index)", async () => {
    const { readdirSync } = await import('node:fs');
    const { BUILTIN_MODELS, DEFAULT_MODEL } = await import('../../src/app/models.ts');
    const files = readdirSync(new URL('../../public/models/', import.meta.url))
      .filter((f) => f.endsWith('.obj'))
      .map((f) => f.slice(0, -4));
    expect(BUILTIN_MODELS.map((m) => m.name).sort()).toEqual(files.sort());
    expect(BUILTIN_MODELS.map((m) => m.name)).toContain(DEFAULT_MODEL);
    expect(new Set(BUILTIN_MODELS.map((m) => m.label)).size).toBe(BUILTIN_MODELS.length);
  });
});
