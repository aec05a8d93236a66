contactforces = [
];
