stresses = [
];
