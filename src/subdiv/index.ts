export * from './level.ts';
export * from './bspline.ts';
export * from './limit.ts';
export * from './evaluate.ts';
export * from './uniform.ts';
export * from './displace.ts';
export * from './refine-cage.ts';
