import { mountFigurePage } from './figure-page.ts';

mountFigurePage('triangle');
