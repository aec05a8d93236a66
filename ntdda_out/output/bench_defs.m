deformations = [
];
