import { mountFigurePage } from './figure-page.ts';

mountFigurePage('line');
