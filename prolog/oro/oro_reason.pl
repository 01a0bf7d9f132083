:- module(oro_reason,
          [ oro_holds/4,                % +Model, ?S, ?P, ?O
            oro_type/3,                 % +Model, ?X, ?Class
            oro_subclass/3,             % +Model, ?Sub, ?Super
            oro_subproperty/3,          % +Model, ?Sub, ?Super
            oro_class/2,                % +Model, ?Class
            oro_property/3,             % +Model, ?Property, ?Kind
            oro_individual/2,           % +Model, ?X
            oro_same_individual/3,      % +Model, +X, -Y
            oro_functional_property/2,  % +Model, ?Property
            oro_transitive_property/2,  % +Model, ?Property
            oro_literal_match/2,        % +Pattern, +Literal
            oro_meta_namespace/1,       % +IRI
            oro_compile_schema/2,       % +Model, -Key
            oro_drop_schema/1,          % +Key
            oro_with_schemas/2,         % +ModelKeys, :Goal
            oro_pattern_dependencies/3  % +Model, +Triples, -Predicates
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(ordsets)).
:- use_module(library(debug)).
:- use_module(library(error)).
:- use_module(oro_store).

:- meta_predicate
    oro_with_schemas(+, 0).
:- use_module(oro_names).

/** <module> Reasoning: the inference closure of a model

oro answers every question over the *inference closure* of a model:
what was asserted plus what RDFS and the common OWL property axioms
entail.  The mechanism is query-time reasoning over small, precomputed
schema closures:

  - The *schema* of a model (class and property hierarchies,
    owl:equivalentClass/Property, owl:inverseOf, symmetric, transitive
    and functional properties, domains, ranges and owl:sameAs) is
    compiled into closure tables, once per schema change, and cached
    under a key.  A schema change (in any model or the ontology layer)
    bumps oro_store's generation counter; the next reader recompiles.
  - Instance triples are never materialised.  oro_holds/4 derives
    them when asked: a triple `S P O` holds if an asserted triple
    `S Q O` (or `O Q S`) implies it through the precomputed *ways* of
    P (sub-properties, equivalent and inverse properties, symmetry),
    or through the transitive closure of a transitive property that
    implies P.  Types come from asserted types, the class hierarchy,
    domains and ranges.  owl:sameAs individuals share everything.

Why: adding a fact then costs one rdf_assert (bulk adds run at rdf_db
speed), removing a fact removes exactly what it supported (nothing was
derived and stored), and inferences are visible to the very next
request, schema added at run time included.  Lookups stay a few
index probes because the schema closures are small and indexed.
Forward chaining with truth maintenance was the alternative; it costs
several times more per assert (about 7x in a trial, STYLE.md) and makes
removal expensive.

Measured by bench/bench_reasoner.pl (SWI-Prolog 9.0.4, AMD EPYC, 50k
asserted triples over the common-sense ontology, IRIs given): a bare
rdf/3 probe 1.0 us, a triple asserted in the model 0.7 us, `x isOn y`
3.1 us, `x isAt y` through isOn 5.0 us, an asserted type 3.3 us, an
inferred type (Cup under Tableware under Artifact) 4.5 us, a false type
4.8 us; recompiling the schema 4.4 ms, done only on the first question
after a schema change.
*/

:- rdf_meta
    oro_holds(+, r, r, o),
    oro_type(+, r, r),
    oro_subclass(+, r, r),
    oro_subproperty(+, r, r),
    oro_class(+, r),
    oro_property(+, r, ?),
    oro_individual(+, r),
    special_predicate(r),
    meta_class(r),
    bare_type(r, -).

:- dynamic
    schema_key/3,                   % Model, Generation, Key
    s_class/2,                      % Key, Class
    s_sub/3,                        % Key, Sub, Super (reflexive, transitive)
    s_prop/3,                       % Key, Property, Kind
    s_subprop/3,                    % Key, Sub, Super (reflexive, transitive)
    s_way/4,                        % Key, P, Q, Dir: Q-edges imply P
    s_has_ways/2,                   % Key, P
    s_trans_way/4,                  % Key, P, T, Dir: T transitive
    s_transitive/2,                 % Key, P
    s_functional/2,                 % Key, P
    s_subj_implies/3,               % Key, Q, Class
    s_obj_implies/3,                % Key, Q, Class
    s_same/3,                       % Key, X, Members
    s_has_same/1.                   % Key

		 /*******************************
		 *            SCHEMA            *
		 *******************************/

%!  schema(+Model, -Key) is det.
%
%   Key identifies the up-to-date schema closure tables of Model,
%   compiling them if the schema changed since they were made.

schema(Model, Key) :-
    nb_current(oro_schema_keys, Keys),
    memberchk(Model-Key0, Keys),
    !,
    Key = Key0.
schema(Model, Key) :-
    oro_schema_generation(Gen),
    (   schema_key(Model, Gen, Key0)
    ->  Key = Key0
    ;   with_mutex(oro_schema, compile_schema_once(Model, Gen, Key))
    ).

%   The tables are kept for Gen only if no schema change started while
%   they were compiled (oro_store bumps the generation before a schema
%   change becomes visible and again once it is committed or rolled
%   back), so a cached key never holds a schema older or newer than its
%   generation.

compile_schema_once(Model, Gen, Key) :-
    (   schema_key(Model, Gen, Key0)
    ->  Key = Key0
    ;   flag(oro_schema_key, Key, Key+1),
        compile_schema(Model, Key),
        oro_schema_generation(Gen1),
        (   Gen1 == Gen
        ->  forall(retract(schema_key(Model, _, Old)),
                   drop_schema(Old)),
            assertz(schema_key(Model, Gen, Key)),
            debug(oro(reason), 'Schema of ~q compiled as ~q (generation ~q)',
                  [Model, Key, Gen])
        ;   drop_schema(Key)
        )
    ).

%!  oro_compile_schema(+Model, -Key) is det.
%
%   Compile the schema of Model as the calling thread sees the store
%   now (in a snapshot, for instance) into fresh tables identified by
%   Key, outside the shared cache.  Use it with oro_with_schemas/2 and
%   release it with oro_drop_schema/1.  The event watcher uses this to
%   evaluate each change with the schema of that very change.

oro_compile_schema(Model, Key) :-
    must_be(atom, Model),
    flag(oro_schema_key, Key, Key+1),
    compile_schema(Model, Key).

%!  oro_drop_schema(+Key) is det.
%
%   Release tables made by oro_compile_schema/2.

oro_drop_schema(Key) :-
    must_be(integer, Key),
    retract_schema(Key).

%!  oro_with_schemas(+ModelKeys, :Goal) is semidet.
%
%   Run Goal (once) with the schema tables of each Model-Key pair of
%   ModelKeys instead of the shared cache, in this thread.

oro_with_schemas(ModelKeys, Goal) :-
    must_be(list, ModelKeys),
    (   nb_current(oro_schema_keys, Old)
    ->  true
    ;   Old = []
    ),
    setup_call_cleanup(
        b_setval(oro_schema_keys, ModelKeys),
        once(Goal),
        b_setval(oro_schema_keys, Old)).


%   Tables of an old key are dropped one compilation later, so a reader
%   that started with it does not see them vanish.

:- dynamic retired/1.

drop_schema(Key) :-
    forall(retract(retired(Old)), retract_schema(Old)),
    assertz(retired(Key)).

retract_schema(Key) :-
    retractall(s_class(Key, _)),
    retractall(s_sub(Key, _, _)),
    retractall(s_prop(Key, _, _)),
    retractall(s_subprop(Key, _, _)),
    retractall(s_way(Key, _, _, _)),
    retractall(s_has_ways(Key, _)),
    retractall(s_trans_way(Key, _, _, _)),
    retractall(s_transitive(Key, _)),
    retractall(s_functional(Key, _)),
    retractall(s_subj_implies(Key, _, _)),
    retractall(s_obj_implies(Key, _, _)),
    retractall(s_same(Key, _, _)),
    retractall(s_has_same(Key)).

compile_schema(Model, Key) :-
    compile_classes(Model, Key),
    compile_properties(Model, Key),
    compile_implications(Model, Key),
    compile_same_as(Model, Key).

schema_pairs(Model, P, Pairs) :-
    findall(S-O, oro_asserted(Model, S, P, O), Pairs0),
    sort(Pairs0, Pairs).

%   Classes and their reflexive-transitive super classes.

compile_classes(Model, Key) :-
    rdf_equal(rdfs:subClassOf, SubClassOf),
    rdf_equal(owl:equivalentClass, Equivalent),
    schema_pairs(Model, SubClassOf, Subs),
    schema_pairs(Model, Equivalent, Eqs),
    findall(C, declared_class(Model, C), Declared),
    pairs_keys_values(Subs, SubKeys, SubValues),
    pairs_keys_values(Eqs, EqKeys, EqValues),
    append([Declared, SubKeys, SubValues, EqKeys, EqValues], Classes0),
    rdf_equal(owl:'Thing', Thing),
    sort([Thing|Classes0], Classes),
    findall(A-B, ( member(A-B, Subs)
                 ; member(A-B, Eqs)
                 ; member(B-A, Eqs)
                 ), Edges0),
    sort(Edges0, Edges),
    edges_graph(Classes, Edges, Graph),
    forall(member(C, Classes),
           ( assertz(s_class(Key, C)),
             reachable(Graph, C, Supers),
             forall(member(D, [C, Thing|Supers]),
                    assert_once(s_sub(Key, C, D)))
           )).

declared_class(Model, C) :-
    rdf_equal(rdf:type, Type),
    (   rdf_equal(owl:'Class', Meta)
    ;   rdf_equal(rdfs:'Class', Meta)
    ),
    oro_asserted(Model, C, Type, Meta).
declared_class(Model, C) :-
    (   rdf_equal(rdfs:domain, P)
    ;   rdf_equal(rdfs:range, P)
    ),
    oro_asserted(Model, _, P, C),
    atom(C),
    \+ datatype(C).
declared_class(Model, C) :-
    (   rdf_equal(owl:disjointWith, P)
    ;   rdf_equal(owl:complementOf, P)
    ),
    (   oro_asserted(Model, C, P, _)
    ;   oro_asserted(Model, _, P, C)
    ).

datatype(C) :-
    rdf_equal(rdfs:'Literal', C),
    !.
datatype(C) :-
    rdf_equal(xsd:'', XSD),
    sub_atom(C, 0, _, _, XSD).

assert_once(Fact) :-
    (   call(Fact)
    ->  true
    ;   assertz(Fact)
    ).

%!  edges_graph(+Nodes, +Edges, -Graph) is det.
%!  reachable(+Graph, +Node, -Reached) is det.
%
%   Graph is an assoc from each node to its direct successors; Reached
%   is the ordered set of nodes reachable from Node in one or more steps
%   (Node itself only through a cycle, which equivalence creates).

edges_graph(Nodes, Edges, Graph) :-
    findall(N-[], member(N, Nodes), Empty),
    list_to_assoc(Empty, Graph0),
    foldl(add_edge, Edges, Graph0, Graph).

add_edge(A-B, G0, G) :-
    (   get_assoc(A, G0, Succ)
    ->  put_assoc(A, G0, [B|Succ], G)
    ;   put_assoc(A, G0, [B], G)
    ).

reachable(Graph, Node, Reached) :-
    successors(Graph, Node, Start),
    closure(Start, Graph, [], Reached).

closure([], _, Seen, Reached) :-
    sort(Seen, Reached).
closure([H|T], Graph, Seen, Reached) :-
    (   memberchk(H, Seen)
    ->  closure(T, Graph, Seen, Reached)
    ;   successors(Graph, H, Next),
        append(Next, T, Queue),
        closure(Queue, Graph, [H|Seen], Reached)
    ).

successors(Graph, Node, Succ) :-
    (   get_assoc(Node, Graph, Succ0)
    ->  Succ = Succ0
    ;   Succ = []
    ).

%   Properties: hierarchy, characteristics and the ways asserted edges
%   imply each property.

compile_properties(Model, Key) :-
    rdf_equal(rdfs:subPropertyOf, SubPropertyOf),
    rdf_equal(owl:equivalentProperty, Equivalent),
    rdf_equal(owl:inverseOf, InverseOf),
    schema_pairs(Model, SubPropertyOf, Subs),
    schema_pairs(Model, Equivalent, Eqs),
    schema_pairs(Model, InverseOf, Invs),
    findall(P-Kind, declared_property(Model, P, Kind), Declared),
    findall(P, ( member(P-_, Declared)
               ; member(P-_, Subs) ; member(_-P, Subs)
               ; member(P-_, Eqs) ; member(_-P, Eqs)
               ; member(P-_, Invs) ; member(_-P, Invs)
               ), Props0),
    sort(Props0, Props),
    forall(member(P, Props),
           ( property_kind(P, Declared, Kind),
             assertz(s_prop(Key, P, Kind))
           )),
    findall(A-B, ( member(A-B, Subs)
                 ; member(A-B, Eqs)
                 ; member(B-A, Eqs)
                 ), SubEdges0),
    sort(SubEdges0, SubEdges),
    edges_graph(Props, SubEdges, SubGraph),
    forall(member(P, Props),
           ( reachable(SubGraph, P, Supers),
             forall(member(Q, [P|Supers]),
                    assert_once(s_subprop(Key, P, Q)))
           )),
    forall(characteristic(Model, P, transitive),
           assert_once(s_transitive(Key, P))),
    forall(characteristic(Model, P, functional),
           assert_once(s_functional(Key, P))),
    findall(P, characteristic(Model, P, symmetric), Symmetric0),
    sort(Symmetric0, Symmetric),
    % ways: from (P, fwd), walk to sub-properties, inverses, symmetry
    findall(Super-Sub, member(Sub-Super, SubEdges), DownEdges),
    edges_graph(Props, DownEdges, DownGraph),
    findall(A-B, ( member(A-B, Invs) ; member(B-A, Invs) ), InvEdges),
    edges_graph(Props, InvEdges, InvGraph),
    forall(member(P, Props),
           ( ways(P, DownGraph, InvGraph, Symmetric, Ways),
             assertz(s_has_ways(Key, P)),
             forall(member(Q-Dir, Ways),
                    ( assertz(s_way(Key, P, Q, Dir)),
                      (   s_transitive(Key, Q)
                      ->  assertz(s_trans_way(Key, P, Q, Dir))
                      ;   true
                      )
                    ))
           )).

declared_property(Model, P, Kind) :-
    rdf_equal(rdf:type, Type),
    property_class(Class, Kind),
    oro_asserted(Model, P, Type, Class).
declared_property(Model, P, other) :-
    (   rdf_equal(rdfs:domain, D)
    ;   rdf_equal(rdfs:range, D)
    ),
    oro_asserted(Model, P, D, _).

:- rdf_meta property_class(r, -), characteristic_class(r, -).

property_class(owl:'ObjectProperty', object).
property_class(owl:'DatatypeProperty', datatype).
property_class(owl:'AnnotationProperty', annotation).
property_class(rdf:'Property', other).
property_class(owl:'TransitiveProperty', object).
property_class(owl:'SymmetricProperty', object).
property_class(owl:'FunctionalProperty', other).
property_class(owl:'InverseFunctionalProperty', object).

property_kind(P, Declared, Kind) :-
    (   memberchk(P-object, Declared)
    ->  Kind = object
    ;   memberchk(P-datatype, Declared)
    ->  Kind = datatype
    ;   memberchk(P-annotation, Declared)
    ->  Kind = annotation
    ;   Kind = other
    ).

characteristic(Model, P, Char) :-
    rdf_equal(rdf:type, Type),
    characteristic_class(Class, Char),
    oro_asserted(Model, P, Type, Class).

characteristic_class(owl:'TransitiveProperty', transitive).
characteristic_class(owl:'SymmetricProperty', symmetric).
characteristic_class(owl:'FunctionalProperty', functional).

ways(P, DownGraph, InvGraph, Symmetric, Ways) :-
    way_closure([P-fwd], DownGraph, InvGraph, Symmetric, [], Ways).

way_closure([], _, _, _, Seen, Ways) :-
    sort(Seen, Ways).
way_closure([Q-D|T], Down, Inv, Sym, Seen, Ways) :-
    (   memberchk(Q-D, Seen)
    ->  way_closure(T, Down, Inv, Sym, Seen, Ways)
    ;   flip(D, F),
        successors(Down, Q, Subs),
        successors(Inv, Q, Invs),
        findall(S-D, member(S, Subs), Next1),
        findall(I-F, member(I, Invs), Next2),
        (   memberchk(Q, Sym)
        ->  Next3 = [Q-F]
        ;   Next3 = []
        ),
        append([Next1, Next2, Next3, T], Queue),
        way_closure(Queue, Down, Inv, Sym, [Q-D|Seen], Ways)
    ).

flip(fwd, bwd).
flip(bwd, fwd).

%   Domains and ranges: which asserted edges imply which types.

compile_implications(Model, Key) :-
    rdf_equal(rdfs:domain, Domain),
    rdf_equal(rdfs:range, Range),
    schema_pairs(Model, Domain, Domains),
    schema_pairs(Model, Range, Ranges),
    forall(( member(P-C, Domains),
             atom(C),
             way(Key, P, Q, Dir),
             sub_class_of(Key, C, Super)
           ),
           (   Dir == fwd
           ->  assert_once(s_subj_implies(Key, Q, Super))
           ;   assert_once(s_obj_implies(Key, Q, Super))
           )),
    forall(( member(P-C, Ranges),
             atom(C),
             \+ datatype(C),
             way(Key, P, Q, Dir),
             sub_class_of(Key, C, Super)
           ),
           (   Dir == fwd
           ->  assert_once(s_obj_implies(Key, Q, Super))
           ;   assert_once(s_subj_implies(Key, Q, Super))
           )).

%   owl:sameAs equivalence classes.

compile_same_as(Model, Key) :-
    rdf_equal(owl:sameAs, SameAs),
    schema_pairs(Model, SameAs, Pairs),
    (   Pairs == []
    ->  true
    ;   assertz(s_has_same(Key)),
        findall(A-B, ( member(A-B, Pairs) ; member(B-A, Pairs) ), Edges),
        pairs_keys(Edges, Nodes0),
        sort(Nodes0, Nodes),
        edges_graph(Nodes, Edges, Graph),
        forall(member(N, Nodes),
               ( reachable(Graph, N, Reached),
                 ord_union([N], Reached, Members),
                 assertz(s_same(Key, N, Members))
               ))
    ).

		 /*******************************
		 *        SCHEMA ACCESS         *
		 *******************************/

%   sub_class_of(+Key, ?Sub, ?Super): reflexive; a class unknown to
%   the schema (only used as a type) is its own class under owl:Thing.

sub_class_of(Key, Sub, Super) :-
    (   nonvar(Sub),
        \+ s_class(Key, Sub)
    ->  (   Super = Sub
        ;   \+ oro_meta_namespace(Sub),
            rdf_equal(owl:'Thing', Super)
        )
    ;   s_sub(Key, Sub, Super)
    ).

way(Key, P, Q, Dir) :-
    (   s_has_ways(Key, P)
    ->  s_way(Key, P, Q, Dir)
    ;   Q = P,
        Dir = fwd
    ).

same(Key, X, Y) :-
    (   s_same(Key, X, Members)
    ->  member(Y, Members)
    ;   Y = X
    ).

%!  oro_meta_namespace(+IRI) is semidet.
%
%   IRI is in the rdf, rdfs, owl or xsd namespace.

oro_meta_namespace(IRI) :-
    atom(IRI),
    (   rdf_equal(rdf:'', NS)
    ;   rdf_equal(rdfs:'', NS)
    ;   rdf_equal(owl:'', NS)
    ;   rdf_equal(xsd:'', NS)
    ),
    sub_atom(IRI, 0, _, _, NS),
    !.

		 /*******************************
		 *           HOLDS              *
		 *******************************/

%!  oro_holds(+Model, ?S, ?P, ?O) is nondet.
%
%   The triple S-P-O is in the inference closure of Model.  Each
%   distinct triple is returned once; with S, P and O bound it is
%   semidet.  Literal objects match by value (`12` matches
%   `"12"^^xsd:integer`; strings ignore language tags).

oro_holds(Model, S0, P0, O0) :-
    oro_resource(S0, S),
    oro_resource(P0, P),
    oro_object(O0, O),
    schema(Model, Key),
    (   ground(S-P-O)
    ->  holds(Key, Model, S, P, O),
        !
    ;   findall(S-P-O, holds(Key, Model, S, P, O), Triples0),
        sort(Triples0, Triples),
        member(S-P-O, Triples),
        \+ rdf_is_bnode(P)
    ).

holds(Key, Model, S, P, O) :-
    var(P),
    !,
    candidate_predicate(Key, Model, S, O, P),
    holds(Key, Model, S, P, O).
holds(Key, Model, S, P, O) :-
    special_predicate(P),
    !,
    special_holds(P, Key, Model, S, O).
holds(Key, Model, S, P, O) :-
    step(Key, Model, P, S, O).
holds(Key, Model, S, P, O) :-
    s_trans_way(Key, P, T, Dir),
    (   Dir == fwd
    ->  transitive(Key, Model, T, S, O)
    ;   transitive(Key, Model, T, O, S)
    ).

special_predicate(rdf:type).
special_predicate(rdfs:subClassOf).
special_predicate(rdfs:subPropertyOf).
special_predicate(owl:sameAs).

special_holds(P, Key, Model, S, O) :-
    rdf_equal(P, rdf:type),
    !,
    type(Key, Model, S, O).
special_holds(P, Key, Model, S, O) :-
    rdf_equal(P, rdfs:subClassOf),
    !,
    (   nonvar(S)
    ->  class_key(Key, Model, S),
        sub_class_of(Key, S, O)
    ;   s_sub(Key, S, O)
    ).
special_holds(P, Key, _Model, S, O) :-
    rdf_equal(P, rdfs:subPropertyOf),
    !,
    s_subprop(Key, S, O).
special_holds(_SameAs, Key, Model, S, O) :-
    (   nonvar(S)
    ->  same_as_known(Key, Model, S),
        same(Key, S, O)
    ;   nonvar(O)
    ->  same_as_known(Key, Model, O),
        same(Key, O, S)
    ;   s_same(Key, S, Members),
        member(O, Members)
    ).

same_as_known(Key, Model, X) :-
    (   s_same(Key, X, _)
    ->  true
    ;   individual_key(Key, Model, X)
    ).

%   One step: an asserted edge implying P, through its ways, with
%   owl:sameAs substitution.

step(Key, Model, P, S, O) :-
    way(Key, P, Q, Dir),
    (   Dir == fwd
    ->  asserted_same(Key, Model, S, Q, O)
    ;   asserted_same(Key, Model, O, Q, S)
    ).

asserted_same(Key, Model, S, Q, O) :-
    (   s_has_same(Key)
    ->  same_in(Key, S, S1),
        same_in(Key, O, O1),
        asserted_match(Model, S1, Q, O1),
        same_out(Key, S1, S),
        same_out(Key, O1, O)
    ;   asserted_match(Model, S, Q, O)
    ).

same_in(Key, X, Y) :-
    (   var(X)
    ->  true
    ;   same(Key, X, Y)
    ).

same_out(Key, Y, X) :-
    (   var(X)
    ->  same(Key, Y, X)
    ;   true
    ).

%   asserted_match(+Model, ?S, +Q, ?O): an asserted triple, literal
%   objects compared by value.

asserted_match(Model, S, Q, O) :-
    (   nonvar(O),
        O = literal(_)
    ->  literal_asserted(Model, S, Q, O)
    ;   oro_asserted(Model, S, Q, O)
    ).

literal_asserted(Model, S, Q, Pattern) :-
    (   nonvar(S)
    ->  oro_asserted(Model, S, Q, Literal),
        oro_literal_match(Pattern, Literal)
    ;   literal_key(Pattern, string(Text))
    ->  atom_string(Lex, Text),
        rdf(S, Q, literal(exact(Lex), Value)),
        Literal = literal(Value),
        oro_literal_match(Pattern, Literal),
        once(oro_asserted(Model, S, Q, Literal))
    ;   oro_asserted(Model, S, Q, Literal),
        oro_literal_match(Pattern, Literal)
    ).

%!  oro_literal_match(+Pattern, +Literal) is semidet.
%
%   The two literals have the same value: numbers compare numerically
%   whatever their numeric datatype, booleans by truth value, and
%   strings by their text, ignoring language tags and xsd:string.

oro_literal_match(Pattern, Literal) :-
    literal_key(Pattern, K1),
    literal_key(Literal, K2),
    same_key(K1, K2).

same_key(number(X), number(Y)) :-
    !,
    X =:= Y.
same_key(K, K).

literal_key(literal(Value), Key) :-
    value_key(Value, Key).

value_key(type(Type, Lex), Key) :-
    !,
    (   bare_type(Type, Kind),
        typed_key(Kind, Lex, Key0)
    ->  Key = Key0
    ;   atom_string(Lex, String),
        (   rdf_equal(Type, xsd:string)
        ->  Key = string(String)
        ;   Key = typed(Type, String)
        )
    ).
value_key(lang(_, Lex), string(String)) :-
    !,
    atom_string(Lex, String).
value_key(Lex, string(String)) :-
    atom_string(Lex, String).

typed_key(number, Lex, number(N)) :-
    atom_number(Lex, N).
typed_key(boolean, Lex, boolean(B)) :-
    boolean_lexical(Lex, B).

boolean_lexical(true, true).
boolean_lexical('1', true).
boolean_lexical(false, false).
boolean_lexical('0', false).

bare_type(xsd:int, number).
bare_type(xsd:integer, number).
bare_type(xsd:long, number).
bare_type(xsd:short, number).
bare_type(xsd:byte, number).
bare_type(xsd:nonNegativeInteger, number).
bare_type(xsd:positiveInteger, number).
bare_type(xsd:negativeInteger, number).
bare_type(xsd:nonPositiveInteger, number).
bare_type(xsd:unsignedInt, number).
bare_type(xsd:unsignedLong, number).
bare_type(xsd:double, number).
bare_type(xsd:float, number).
bare_type(xsd:decimal, number).
bare_type(xsd:boolean, boolean).

%   Transitive closure of the edges implying T, breadth first, from a
%   bound end.  With both ends unbound, from every subject of an edge.

transitive(Key, Model, T, S, O) :-
    (   nonvar(S)
    ->  reach(Key, Model, T, fwd, S, O)
    ;   nonvar(O)
    ->  reach(Key, Model, T, bwd, O, S)
    ;   findall(S0, step(Key, Model, T, S0, _), Starts0),
        sort(Starts0, Starts),
        member(S, Starts),
        reach(Key, Model, T, fwd, S, O)
    ).

reach(Key, Model, T, Dir, From, To) :-
    (   nonvar(To)
    ->  reach_set(Key, Model, T, Dir, [From], [], To, Reached),
        memberchk(To, Reached)
    ;   reach_set(Key, Model, T, Dir, [From], [], _, Reached),
        member(To, Reached)
    ).

%   reach_set(..., +Queue, +Seen, ?Goal, -Reached): stops early once
%   Goal (if bound) is reached.

reach_set(_, _, _, _, [], Seen, _, Seen) :- !.
reach_set(_, _, _, _, _, Seen, Goal, Seen) :-
    nonvar(Goal),
    memberchk(Goal, Seen),
    !.
reach_set(Key, Model, T, Dir, [X|Queue], Seen, Goal, Reached) :-
    findall(Y, ( next(Key, Model, T, Dir, X, Y),
                 Y \= literal(_),
                 \+ memberchk(Y, Seen)
               ), Next0),
    sort(Next0, Next),
    append(Seen, Next, Seen1),
    append(Queue, Next, Queue1),
    reach_set(Key, Model, T, Dir, Queue1, Seen1, Goal, Reached).

next(Key, Model, T, fwd, X, Y) :-
    step(Key, Model, T, X, Y).
next(Key, Model, T, bwd, X, Y) :-
    step(Key, Model, T, Y, X).

%   Predicates that may hold between S and O when P is unbound.

candidate_predicate(Key, Model, S, O, P) :-
    findall(P0, candidate_predicate_(Key, Model, S, O, P0), Ps0),
    sort(Ps0, Ps),
    member(P, Ps).

candidate_predicate_(Key, Model, S, O, P) :-
    (   nonvar(S)
    ->  same_in(Key, S, S1),
        oro_asserted(Model, S1, Q, _),
        used_as(Key, Q, fwd, P)
    ;   nonvar(O)
    ->  same_in(Key, O, O1),
        oro_asserted(Model, _, Q, O1),
        used_as(Key, Q, fwd, P)
    ;   oro_asserted(Model, _, Q, _),
        used_as(Key, Q, fwd, P)
    ).
candidate_predicate_(Key, Model, S, O, P) :-
    (   nonvar(S)
    ->  same_in(Key, S, S1),
        oro_asserted(Model, _, Q, S1)
    ;   nonvar(O)
    ->  same_in(Key, O, O1),
        oro_asserted(Model, O1, Q, _)
    ),
    used_as(Key, Q, bwd, P).
candidate_predicate_(_, _, _, _, P) :-
    special_predicate(P).

used_as(Key, Q, Dir, P) :-
    (   s_way(Key, P, Q, Dir)
    *-> true
    ;   Dir == fwd,
        P = Q
    ).

		 /*******************************
		 *            TYPES             *
		 *******************************/

type(Key, Model, X, C) :-
    (   nonvar(X)
    ->  (   nonvar(C)
        ->  has_type(Key, Model, X, C),
            !
        ;   types_of(Key, Model, X, Types),
            member(C, Types)
        )
    ;   nonvar(C)
    ->  instances_of(Key, Model, C, Instances),
        member(X, Instances)
    ;   findall(X0, individual_key(Key, Model, X0), Xs),
        member(X, Xs),
        types_of(Key, Model, X, Types),
        member(C, Types)
    ).

has_type(Key, Model, X, C) :-
    rdf_equal(owl:'Thing', C),
    !,
    same(Key, X, X1),
    individual_key(Key, Model, X1).
has_type(Key, Model, X, C) :-
    rdf_equal(rdf:type, Type),
    same(Key, X, X1),
    (   oro_asserted(Model, X1, Type, D),
        sub_class_of(Key, D, C)
    ;   s_subj_implies(Key, Q, C),
        oro_asserted(Model, X1, Q, _)
    ;   s_obj_implies(Key, Q, C),
        oro_asserted(Model, _, Q, X1)
    ).

types_of(Key, Model, X, Types) :-
    rdf_equal(rdf:type, Type),
    findall(C, ( same(Key, X, X1),
                 (   oro_asserted(Model, X1, Type, D),
                     sub_class_of(Key, D, C)
                 ;   oro_asserted(Model, X1, Q, _),
                     s_subj_implies(Key, Q, C)
                 ;   oro_asserted(Model, _, Q, X1),
                     s_obj_implies(Key, Q, C)
                 ;   individual_key(Key, Model, X1),
                     rdf_equal(owl:'Thing', C)
                 )
               ), Types0),
    sort(Types0, Types).

instances_of(Key, Model, C, Instances) :-
    rdf_equal(owl:'Thing', C),
    !,
    findall(X, individual_key(Key, Model, X), Instances).
instances_of(Key, Model, C, Instances) :-
    rdf_equal(rdf:type, Type),
    findall(X, ( (   s_sub(Key, D, C),
                     oro_asserted(Model, X1, Type, D)
                 ;   \+ s_class(Key, C),
                     oro_asserted(Model, X1, Type, C)
                 ;   s_subj_implies(Key, Q, C),
                     oro_asserted(Model, X1, Q, _)
                 ;   s_obj_implies(Key, Q, C),
                     oro_asserted(Model, _, Q, X1),
                     atom(X1)
                 ),
                 same(Key, X1, X)
               ), Instances0),
    sort(Instances0, Instances).

%   Individuals: typed with a non-meta class, or subject or object of
%   an instance-level triple.

individual_key(Key, Model, X) :-
    nonvar(X),
    !,
    same(Key, X, X1),
    individual_evidence(Model, X1),
    !.
individual_key(Key, Model, X) :-
    findall(X0, individual_candidate(Model, X0), Xs0),
    sort(Xs0, Xs1),
    include(is_individual(Model), Xs1, Xs2),
    findall(X1, ( member(X0, Xs2), same(Key, X0, X1) ), Xs3),
    sort(Xs3, Xs),
    member(X, Xs).

is_individual(Model, X) :-
    individual_evidence(Model, X),
    !.

individual_evidence(Model, X) :-
    rdf_equal(rdf:type, Type),
    oro_asserted(Model, X, Type, C),
    \+ meta_class(C).
individual_evidence(Model, X) :-
    oro_asserted(Model, X, Q, _),
    instance_predicate(Q).
individual_evidence(Model, X) :-
    oro_asserted(Model, _, Q, X),
    instance_predicate(Q).

individual_candidate(Model, X) :-
    oro_asserted(Model, S, Q, O),
    (   rdf_equal(rdf:type, Q)
    ->  \+ meta_class(O),
        X = S
    ;   instance_predicate(Q)
    ->  (   X = S
        ;   atom(O),
            X = O
        )
    ).

instance_predicate(Q) :-
    (   \+ oro_meta_namespace(Q)
    ->  true
    ;   rdf_equal(Q, owl:sameAs)
    ;   rdf_equal(Q, owl:differentFrom)
    ).

meta_class(C) :-
    oro_schema_class(C).
meta_class(owl:'Ontology').
meta_class(owl:'AllDifferent').
meta_class(owl:'AllDisjointClasses').
meta_class(rdfs:'Datatype').
meta_class(rdf:'List').
meta_class(rdf:'Statement').

		 /*******************************
		 *          PUBLIC API          *
		 *******************************/

%!  oro_type(+Model, ?X, ?Class) is nondet.
%
%   X is an instance of Class in the inference closure of Model.

oro_type(Model, X, Class) :-
    rdf_equal(rdf:type, Type),
    oro_holds(Model, X, Type, Class).

%!  oro_subclass(+Model, ?Sub, ?Super) is nondet.
%
%   Sub is a (reflexive, transitive) sub-class of Super in Model;
%   every class is a sub-class of owl:Thing.

oro_subclass(Model, Sub0, Super0) :-
    oro_resource(Sub0, Sub),
    oro_resource(Super0, Super),
    schema(Model, Key),
    (   var(Sub), var(Super)
    ->  s_sub(Key, Sub, Super)
    ;   nonvar(Sub), nonvar(Super)
    ->  once(sub_class_of(Key, Sub, Super))
    ;   sub_class_of(Key, Sub, Super)
    ).

%!  oro_subproperty(+Model, ?Sub, ?Super) is nondet.
%
%   Sub is a (reflexive, transitive) sub-property of Super in Model.

oro_subproperty(Model, Sub0, Super0) :-
    oro_resource(Sub0, Sub),
    oro_resource(Super0, Super),
    schema(Model, Key),
    (   nonvar(Sub),
        \+ s_prop(Key, Sub, _)
    ->  Super = Sub
    ;   nonvar(Sub), nonvar(Super)
    ->  once(s_subprop(Key, Sub, Super))
    ;   s_subprop(Key, Sub, Super)
    ).

%!  oro_class(+Model, ?Class) is nondet.
%
%   Class is a class of Model: declared, used in the class hierarchy,
%   as a domain or range, or as the type of something.

oro_class(Model, Class0) :-
    oro_resource(Class0, Class),
    schema(Model, Key),
    (   nonvar(Class)
    ->  class_key(Key, Model, Class)
    ;   findall(C, ( s_class(Key, C)
                   ; rdf_equal(rdf:type, Type),
                     oro_asserted(Model, _, Type, C),
                     \+ meta_class(C)
                   ), Classes0),
        sort(Classes0, Classes),
        member(Class, Classes)
    ).

class_key(Key, Model, Class) :-
    (   s_class(Key, Class)
    ->  true
    ;   rdf_equal(rdf:type, Type),
        once(oro_asserted(Model, _, Type, Class)),
        \+ meta_class(Class)
    ).

%!  oro_property(+Model, ?Property, ?Kind) is nondet.
%
%   Property is a property of Model, of Kind `object`, `datatype`,
%   `annotation` or `other`.  A predicate that is used but not
%   declared is typed by its values, as OWL reasoners do: `datatype`
%   if it has a literal value, `object` otherwise.

oro_property(Model, Property0, Kind) :-
    oro_resource(Property0, Property),
    schema(Model, Key),
    (   nonvar(Property)
    ->  (   s_prop(Key, Property, Kind0)
        ->  true
        ;   once(oro_asserted(Model, _, Property, _))
        ->  Kind0 = other
        ),
        used_kind(Model, Property, Kind0, Kind)
    ;   findall(P-K, s_prop(Key, P, K), Declared),
        findall(P-other, ( rdf_current_predicate(P),
                           \+ s_prop(Key, P, _),
                           \+ oro_meta_namespace(P),
                           once(oro_asserted(Model, _, P, _))
                         ), Used),
        append(Declared, Used, All0),
        sort(All0, All),
        member(Property-Kind0, All),
        used_kind(Model, Property, Kind0, Kind)
    ).

used_kind(Model, Property, other, Kind) :-
    !,
    (   oro_asserted(Model, _, Property, O),
        O = literal(_)
    ->  Kind = datatype
    ;   once(oro_asserted(Model, _, Property, _))
    ->  Kind = object
    ;   Kind = other
    ).
used_kind(_, _, Kind, Kind).

%!  oro_individual(+Model, ?X) is nondet.
%
%   X is a named individual of Model (an instance of owl:Thing).

oro_individual(Model, X0) :-
    oro_resource(X0, X),
    schema(Model, Key),
    individual_key(Key, Model, X).

%!  oro_same_individual(+Model, +X, -Y) is multi.
%
%   Y is X or an individual owl:sameAs X.

oro_same_individual(Model, X0, Y) :-
    oro_resource(X0, X),
    schema(Model, Key),
    same(Key, X, Y).

%!  oro_functional_property(+Model, ?Property) is nondet.
%
%   Property is declared owl:FunctionalProperty in Model.

oro_functional_property(Model, Property) :-
    schema(Model, Key),
    s_functional(Key, Property).

%!  oro_transitive_property(+Model, ?Property) is nondet.
%
%   Property is declared owl:TransitiveProperty in Model.

oro_transitive_property(Model, Property) :-
    schema(Model, Key),
    s_transitive(Key, Property).

%!  oro_pattern_dependencies(+Model, +Triples, -Predicates) is det.
%
%   Predicates is the ordered set of predicates whose asserted triples
%   can change the solutions of the patterns Triples in Model, through
%   sub-properties, inverses, symmetry, transitivity, domains, ranges
%   and owl:sameAs; it is `[any]` when any triple can (a variable
%   predicate, a variable class, owl:Thing).  Schema changes are not
%   covered: they can change anything.

oro_pattern_dependencies(Model, Triples, Predicates) :-
    must_be(list, Triples),
    schema(Model, Key),
    (   member(rdf(_, P, O), Triples),
        depends_on_any(P, O)
    ->  Predicates = [any]
    ;   findall(Q, ( member(rdf(_, P, O), Triples),
                     pattern_dependency(Key, P, O, Q)
                   ), Qs),
        rdf_equal(owl:sameAs, SameAs),
        sort([SameAs|Qs], Predicates)
    ).

depends_on_any(P, _) :-
    var(P),
    !.
depends_on_any(P, O) :-
    rdf_equal(P, rdf:type),
    (   var(O)
    ->  true
    ;   rdf_equal(O, owl:'Thing')
    ).

pattern_dependency(Key, P, O, Q) :-
    rdf_equal(P, rdf:type),
    !,
    (   Q = P
    ;   s_subj_implies(Key, Q, O)
    ;   s_obj_implies(Key, Q, O)
    ).
pattern_dependency(_, P, _, _) :-
    (   rdf_equal(P, rdfs:subClassOf)
    ;   rdf_equal(P, rdfs:subPropertyOf)
    ),
    !,
    fail.
pattern_dependency(Key, P, _, Q) :-
    (   way(Key, P, Q, _)
    ;   s_trans_way(Key, P, T, _),
        way(Key, T, Q, _)
    ).
