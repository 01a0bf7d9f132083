:- use_module(library(plunit)).
:- use_module(oro_test_support).
:- use_module(library(oro)).

/*  Tests for names (ORO-SPEC §4.1): expansion of the names clients
    write into IRIs (oro_name_iri/2), contraction of IRIs into the ids
    clients read (oro_iri_name/2), and the text of literals in results
    (oro_term_text/2, §4.2 "Output of literals").

    These are pure functions: no store is needed.

    Run: cd /work/main && swipl -g run_tests -t halt test/test_names.pl
*/

:- use_module(library(semweb/rdf_db)).
:- use_module(library(oro/oro_names)).


                 /*******************************
                 *           EXPANSION          *
                 *******************************/

:- begin_tests(name_expansion).

test(default_namespace, true(IRI == 'http://kb.openrobots.org#Monkey')) :-
    oro_name_iri('Monkey', IRI).
test(default_namespace_string, true(IRI == 'http://kb.openrobots.org#baboon')) :-
    oro_name_iri("baboon", IRI).
test(oro_prefix, true(IRI == 'http://kb.openrobots.org#Monkey')) :-
    oro_name_iri('oro:Monkey', IRI).
test(rdf_prefix, true(IRI == 'http://www.w3.org/1999/02/22-rdf-syntax-ns#type')) :-
    oro_name_iri("rdf:type", IRI).
test(rdfs_prefix, true(IRI == 'http://www.w3.org/2000/01/rdf-schema#subClassOf')) :-
    oro_name_iri("rdfs:subClassOf", IRI).
test(owl_prefix, true(IRI == 'http://www.w3.org/2002/07/owl#Thing')) :-
    oro_name_iri('owl:Thing', IRI).
test(xsd_prefix, true(IRI == 'http://www.w3.org/2001/XMLSchema#int')) :-
    oro_name_iri('xsd:int', IRI).
test(cyc_prefix, true(IRI == 'http://sw.opencyc.org/concept/Drink')) :-
    oro_name_iri('cyc:Drink', IRI).
test(full_iri_as_is, true(IRI == 'http://x.org/a#b')) :-
    oro_name_iri('http://x.org/a#b', IRI).
test(full_iri_without_hash, true(IRI == 'http://x.org/a/b')) :-
    oro_name_iri("http://x.org/a/b", IRI).
test(angle_brackets_stripped, true(IRI == 'http://x.org/a#b')) :-
    oro_name_iri('<http://x.org/a#b>', IRI).
test(angle_brackets_default_namespace,
     true(IRI == 'http://kb.openrobots.org#baboon')) :-
    oro_name_iri("<http://kb.openrobots.org#baboon>", IRI).
test(unknown_prefix_stays, true(IRI == 'foo:bar')) :-
    oro_name_iri('foo:bar', IRI).
test(hash_without_prefix_stays, true(IRI == 'a#b')) :-
    oro_name_iri('a#b', IRI).
test(prefix_split_at_first_colon, true(IRI == 'http://kb.openrobots.org#a:b')) :-
    oro_name_iri('oro:a:b', IRI).
test(not_text, error(type_error(text, 42))) :-
    oro_name_iri(42, _).
test(unbound, error(instantiation_error)) :-
    oro_name_iri(_, _).
test(code_list, true(IRI == 'http://www.w3.org/1999/02/22-rdf-syntax-ns#type')) :-
    oro_name_iri(`rdf:type`, IRI).
test(nul_in_name, true(IRI == 'http://kb.openrobots.org#a\u0000b')) :-
    oro_name_iri("a\u0000b", IRI).
test(nul_before_colon, true(IRI == 'a\u0000:b')) :-
    oro_name_iri("a\u0000:b", IRI).

:- end_tests(name_expansion).


/*  Names with a prefix, a `#` or in brackets are expanded through a
    bounded cache (oro_names:name_expansion/2).  A cached expansion must
    be the one computed afresh, for atoms and strings, and the cache
    must stay within its bound.
*/

:- begin_tests(name_cache).

cache_corpus(Name) :-
    member(Name0, [ "rdf:type", "owl:Thing", "oro:a:b", "foo:bar", "x:",
                    ":x", "a#b", "<http://x.org/a#b>", "<>", "<a", "a<b",
                    "a>b", "oro:", "<oro:a>", "\u00e9:x", "xsd:int#"
                  ]),
    (   Name = Name0
    ;   atom_string(Name, Name0)
    ).

test(cached_equals_fresh, Bad == []) :-
    findall(Name-IRI1-IRI2-Fresh,
            ( cache_corpus(Name),
              oro_name_iri(Name, IRI1),         % fills the cache
              oro_name_iri(Name, IRI2),         % from the cache
              oro_names:expand_name(Name, Fresh),
              \+ ( IRI1 == Fresh, IRI2 == Fresh )
            ),
            Bad).
test(atom_and_string_agree, Bad == []) :-
    findall(Name,
            ( cache_corpus(Name),
              string(Name),
              atom_string(Atom, Name),
              oro_name_iri(Name, IRI1),
              oro_name_iri(Atom, IRI2),
              IRI1 \== IRI2
            ),
            Bad).
test(bounded, true(Count =< Max)) :-
    oro_names:name_cache_size(Max),
    Top is 2 * Max + 10,
    forall(between(1, Top, I),
           ( format(string(Name), "p~d:x", [I]),
             oro_name_iri(Name, _)
           )),
    aggregate_all(count, oro_names:name_expansion(_, _), Count).
test(after_flush, true(IRI == 'http://www.w3.org/1999/02/22-rdf-syntax-ns#type')) :-
    oro_names:name_cache_size(Max),
    Top is Max + 1,
    forall(between(1, Top, I),
           ( format(string(Name), "q~d:x", [I]),
             oro_name_iri(Name, _)
           )),
    oro_name_iri("rdf:type", IRI).

:- end_tests(name_cache).


                 /*******************************
                 *          CONTRACTION         *
                 *******************************/

:- begin_tests(name_contraction).

test(default_namespace_dropped, true(Name == baboon)) :-
    oro_iri_name('http://kb.openrobots.org#baboon', Name).
test(owl_prefixed, true(Name == 'owl:Thing')) :-
    oro_iri_name('http://www.w3.org/2002/07/owl#Thing', Name).
test(rdf_prefixed, true(Name == 'rdf:type')) :-
    oro_iri_name('http://www.w3.org/1999/02/22-rdf-syntax-ns#type', Name).
test(rdfs_prefixed, true(Name == 'rdfs:label')) :-
    oro_iri_name('http://www.w3.org/2000/01/rdf-schema#label', Name).
test(xsd_prefixed, true(Name == 'xsd:int')) :-
    oro_iri_name('http://www.w3.org/2001/XMLSchema#int', Name).
test(cyc_prefixed, true(Name == 'cyc:Drink')) :-
    oro_iri_name('http://sw.opencyc.org/concept/Drink', Name).
test(unknown_namespace_full, true(Name == 'http://x.org/a#b')) :-
    oro_iri_name('http://x.org/a#b', Name).
test(namespace_itself_full, true(Name == 'http://kb.openrobots.org#')) :-
    oro_iri_name('http://kb.openrobots.org#', Name).
test(blank_node, true(Name == anonymousNode_b1)) :-
    oro_iri_name('_:b1', Name).
test(round_trip, all(Name == [baboon, 'owl:Thing', 'rdf:type', 'cyc:Drink',
                              'http://x.org/a#b'])) :-
    member(Name0, [baboon, 'owl:Thing', 'rdf:type', 'cyc:Drink',
                   'http://x.org/a#b']),
    oro_name_iri(Name0, IRI),
    oro_iri_name(IRI, Name).
test(resource_term_text, true(Text == 'owl:Thing')) :-
    oro_term_text('http://www.w3.org/2002/07/owl#Thing', Text).
test(resource_term_text_default, true(Text == 'Monkey')) :-
    oro_term_text('http://kb.openrobots.org#Monkey', Text).

:- end_tests(name_contraction).


                 /*******************************
                 *          LOCAL NAMES         *
                 *******************************/

:- begin_tests(local_name).

test(hash, true(L == obj1)) :-
    oro_local_name('http://kb.openrobots.org#obj1', L).
test(slash, true(L == 'Drink')) :-
    oro_local_name('http://sw.opencyc.org/concept/Drink', L).
test(hash_before_slash, true(L == 'b/c')) :-
    oro_local_name('http://x.org/a#b/c', L).
test(last_hash, true(L == c)) :-
    oro_local_name('a#b#c', L).
test(trailing_hash, true(L == '')) :-
    oro_local_name('http://x.org/a#', L).
test(trailing_slash, true(L == '')) :-
    oro_local_name('http://x.org/a/', L).
test(no_separator, true(L == plain)) :-
    oro_local_name(plain, L).
test(agrees_with_split, Bad == []) :-
    findall(IRI-L1-L2,
            ( member(IRI, [ 'http://kb.openrobots.org#obj1', 'a/b/c/d', '#',
                            '/', '//', '##a', 'a#', 'a#b/', 'x/y#z#w/v',
                            'http://www.w3.org/2002/07/owl#Thing', '',
                            'caf\u00e9#th\u00e9', 'a\u0000#b'
                          ]),
              oro_local_name(IRI, L1),
              split_local_name(IRI, L2),
              L1 \== L2
            ),
            Bad).

split_local_name(IRI, Local) :-
    (   atomic_list_concat(Parts, '#', IRI),
        Parts = [_, _|_]
    ->  last(Parts, Local)
    ;   atomic_list_concat(Parts, '/', IRI),
        Parts = [_, _|_]
    ->  last(Parts, Local)
    ;   Local = IRI
    ).

:- end_tests(local_name).


                 /*******************************
                 *           LITERALS           *
                 *******************************/

:- begin_tests(literal_text).

test(unbound, error(instantiation_error)) :-    % was bound to a literal
    oro_term_text(_, _).

test(int, true(Text == '12')) :-
    test_literal(xsd:int, '12', L),
    oro_term_text(L, Text).
test(double, true(Text == '48.5')) :-
    test_literal(xsd:double, '48.5', L),
    oro_term_text(L, Text).
test(boolean, true(Text == true)) :-
    test_literal(xsd:boolean, true, L),
    oro_term_text(L, Text).
test(xsd_string, true(Text == 'Lord of the rings')) :-
    test_literal(xsd:string, 'Lord of the rings', L),
    oro_term_text(L, Text).
test(other_datatype_bare, true(Text == '2014-03-01T10:00:00')) :-
    test_literal(xsd:dateTime, '2014-03-01T10:00:00', L),
    oro_term_text(L, Text).
test(language_tag_dropped, true(Text == 'baboon monkey')) :-
    oro_term_text(literal(lang(en, 'baboon monkey')), Text).
test(plain, true(Text == babouin)) :-
    oro_term_text(literal(babouin), Text).
test(quotes_kept_inside, true(Text == 'say "hi"')) :-
    oro_term_text(literal(lang(en, 'say "hi"')), Text).

%   Numbers are written in canonical form: rdf_db keeps one term for
%   literals of the same value (the lexical form first asserted wins),
%   so the lexical form as stored depends on history.

test(int_canonical, true(Texts == ['7', '7', '-3', '12'])) :-
    maplist(typed_text,
            [t(xsd:int, '+7'), t(xsd:integer, '007'), t(xsd:long, '-03'),
             t(xsd:unsignedShort, '12')], Texts).
test(double_canonical, true(Texts == ['150.0', '48.5', '0.001'])) :-
    maplist(typed_text,
            [t(xsd:double, '150'), t(xsd:decimal, '48.50'),
             t(xsd:float, '1.0e-3')], Texts).
test(not_a_number_kept, true(Texts == ['INF', 'NaN', abc])) :-
    maplist(typed_text,
            [t(xsd:double, 'INF'), t(xsd:double, 'NaN'), t(xsd:int, abc)],
            Texts).
test(canonical_in_statements, true(Text == '150.0')) :-
    test_literal(xsd:double, '150', L),
    oro_term_light_text(L, Text).
test(numeric_datatypes, true(Kinds == [integer, integer, decimal, double])) :-
    maplist(xsd_kind, [int, unsignedByte, decimal, double], Kinds).
test(not_numeric, fail) :-
    rdf_global_id(xsd:dateTime, Type),
    oro_numeric_datatype(Type, _).

:- end_tests(literal_text).

typed_text(t(Type, Lex), Text) :-
    test_literal(Type, Lex, Literal),
    oro_term_text(Literal, Text).

xsd_kind(Local, Kind) :-
    rdf_global_id(xsd:Local, Type),
    oro_numeric_datatype(Type, Kind).
