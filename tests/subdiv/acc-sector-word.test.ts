// The ACC sector word: one layout (SECTOR_WORD_FIELDS) for the CPU's packSector / unpackSector and
// the GPU's ACC_SECTOR_WORD, which the contract makes from it.
import { describe, expect, it } from 'vitest';
import { ACC_SECTOR_WORD } from '../../src/gpu/contract/acc.ts';
import { AccError, packSector, SECTOR_CONE, SECTOR_CORNER, SECTOR_CREASE, SECTOR_SMOOTH, unpackSector } from '../../src/subdiv/acc.ts';

describe('the ACC sector word', () => {
  it('packs as the contract packs it, and unpacks to what was packed', () => {
    let seed = 7;
    const rand = (n: number) => (seed = (seed * 1103515245 + 12345) % 2 ** 31) % n;
    for (let i = 0; i < 2000; i++) {
      const kind = [SECTOR_SMOOTH, SECTOR_CREASE, SECTOR_CORNER, SECTOR_CONE][rand(4)];
      const k = i < 4 ? [0, 1, 2 ** 14 - 1, 3][i] : rand(2 ** 14);
      const a = i < 4 ? [0, 2 ** 16 - 1, 1, 65535][i] : rand(2 ** 16);
      const w = packSector(kind, k, a);
      expect(w).toBe(ACC_SECTOR_WORD.pack({ kind, k, a }));
      expect(unpackSector(w)).toEqual({ kind, k, a });
      expect(ACC_SECTOR_WORD.unpack(w)).toEqual({ kind, k, a });
    }
  });

  it('refuses a value its field cannot hold', () => {
    expect(() => packSector(4, 0, 0)).toThrow(AccError);
    expect(() => packSector(SECTOR_CREASE, 2 ** 14, 0)).toThrow(/k = 16384/);
    expect(() => packSector(SECTOR_CREASE, 2, 2 ** 16)).toThrow(AccError);
  });
});
