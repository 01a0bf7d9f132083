:- module(oro_methods_explain,
          [ oro_explain_values/3        % +Model, +Triples, -Values
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(ordsets)).
:- use_module(library(oro/questions/oro_explain)).
:- use_module(library(oro/questions/oro_consistency)).
:- use_module(library(oro/parse/oro_parse)).
:- use_module(library(oro/oro_names)).
:- use_module(library(oro/oro_store)).

/** <module> ORO methods: explanations

The protocol face of oro_explain, declared as a clause of the method
table oro_methods:method/4.  No other ORO server offers this.

    explain(Set statements)

asks the robot's model (`myself`) why each statement holds.  The reply
is a list with one map per statement, in the order given:

    {"statement":"gorilla rdf:type Animal","entailed":true,
     "asserted":["gorilla rdf:type Monkey"],
     "axioms":["Monkey rdfs:subClassOf Animal"]}

  - `statement`: the statement as understood (names contracted);
  - `entailed`: `true` if it holds in the model (asserted or inferred),
    else `false`, and then the map has no other key;
  - `explained`: only in a map whose statement holds by a derivation
    oro_explain/3 cannot replay (it answers unexplained(Statement):
    its proof search gave up, on a derivation nested deeper than 64 or
    needing a goal already in progress), and then always `false`, in
    place of `asserted` and `axioms`:

        {"statement":"x rdf:type C","entailed":true,"explained":false}

    A map with `asserted` and `axioms` has no `explained` key;
  - `asserted`: the asserted statements the derivation uses;
  - `axioms`: the schema axioms it uses.  Anonymous classes are
    written inline: `(hasColour value red)`, `(owns some Dog)`,
    `(serves only VeganDish)`, `(Woman and Parent)`, `(Dog or Cat)`,
    `{saturday, sunday}`, `(not Monkey)`, `xsd:integer[>= 18]`; a
    property chain as `(hasParent hasParent)`, an inverse property in it
    as `(inverse hasParent)`.

Statements are in the light form of getInfos (`gorilla age 12`).  If
the model is inconsistent, the list goes on with one map per conflict
(at most 20, oro_explain_conflict/2), the asserted statements a
minimal set in conflict:

    {"conflict":"disjoint","about":["cow","Animal","Plant"],
     "asserted":["cow rdf:type Animal","cow rdf:type Plant"],
     "axioms":["Animal owl:disjointWith Plant"]}

`conflict` is one of disjoint, nothing, functional, inverse_functional,
same_and_different, irreflexive, asymmetric, disjoint_properties;
`about` lists the individuals, classes, properties and values involved,
as in oro_conflict/2.  `explain([])` gives the conflicts alone.

A malformed statement, or a pattern (`?x eats apple`), is an error of
the whole request (IllegalStatementException), as for `add`.
*/

:- multifile
    oro_methods:method/4.

oro_methods:method(explain(set), querying,
                   "Explains each statement: whether it holds, the asserted statements and the axioms it rests on; while the model is inconsistent, also the minimal sets of statements in conflict.",
                   oro_methods_explain:m_explain).

m_explain(Statements, list(Values)) :-
    oro_complete_statements(Statements, Triples),
    oro_explain_values(myself, Triples, Values).

%!  oro_explain_values(+Model, +Triples, -Values) is det.
%
%   Values are the maps (oro_protocol value terms) `explain` answers
%   for the rdf(S,P,O) Triples in Model: one a statement, then, if
%   Model is inconsistent, one a conflict.  The KB-API's `explain`
%   gives them for any model.

oro_explain_values(Model, Triples, Values) :-
    maplist(statement_value(Model), Triples, Values0),
    (   oro_consistent(Model)
    ->  Values = Values0
    ;   oro_explain_conflict(Model, Conflicts),
        maplist(conflict_value(Model), Conflicts, ConflictValues),
        append(Values0, ConflictValues, Values)
    ).

statement_value(Model, Triple, map(Pairs)) :-
    statement_text(Triple, Text),
    (   oro_explain(Model, Triple, Explanation)
    ->  explanation_pairs(Model, Explanation, Pairs0),
        Pairs = ["statement"-string(Text), "entailed"-bool(true)|Pairs0]
    ;   Pairs = ["statement"-string(Text), "entailed"-bool(false)]
    ).

explanation_pairs(Model, explanation(_, Facts, Axioms), Pairs) :-
    !,
    sources_pairs(Model, Facts, Axioms, Pairs).
explanation_pairs(_, unexplained(_), ["explained"-bool(false)]).

conflict_value(Model, conflict(Conflict, Facts, Axioms), map(Pairs)) :-
    Conflict =.. [Kind|Args],
    atom_string(Kind, KindText),
    maplist(term_value, Args, About),
    sources_pairs(Model, Facts, Axioms, Pairs0),
    Pairs = ["conflict"-string(KindText), "about"-list(About)|Pairs0].

sources_pairs(Model, Facts, Axioms, ["asserted"-list(FactTexts),
                                     "axioms"-list(AxiomTexts)]) :-
    findall(string(Text), ( member(fact(T, _), Facts),
                            statement_text(T, Text)
                          ), FactTexts),
    axiom_texts(Model, Axioms, Texts),
    maplist(string_value, Texts, AxiomTexts).

term_value(Term, string(Text)) :-
    term_text(Term, Text).

string_value(Text, string(Text)).

statement_text(rdf(S, P, O), Text) :-
    term_text(S, ST),
    term_text(P, PT),
    term_text(O, OT),
    atomic_list_concat([ST, PT, OT], ' ', Atom),
    atom_string(Atom, Text).

term_text(Term, Text) :-
    (   var(Term)
    ->  Text = '?'
    ;   oro_term_light_text(Term, Text)
    ).

		 /*******************************
		 *       AXIOMS AS TEXT         *
		 *******************************/

%   axiom_texts(+Model, +Axioms, -Texts): the axioms that are not part
%   of the description of an anonymous class another axiom uses, with
%   anonymous classes written inline.

axiom_texts(Model, Axioms, Texts) :-
    findall(O, ( member(rdf(_, _, O), Axioms),
                 atom(O),
                 rdf_is_bnode(O)
               ), Inline0),
    sort(Inline0, Inline),
    findall(Text, ( member(Axiom, Axioms),
                    \+ inline_part(Axiom, Inline),
                    axiom_text(Model, Axiom, Text)
                  ), Texts0),
    sort(Texts0, Texts).

inline_part(rdf(S, _, _), Inline) :-
    ord_memberchk(S, Inline),
    !.
inline_part(rdf(S, P, _), _) :-
    rdf_is_bnode(S),
    (   rdf_equal(P, rdf:first)
    ;   rdf_equal(P, rdf:rest)
    ),
    !.
inline_part(rdf(S, P, O), _) :-
    rdf_is_bnode(S),
    rdf_equal(P, rdf:type),
    (   rdf_equal(O, owl:'Restriction')
    ;   rdf_equal(O, owl:'Class')
    ;   rdf_equal(O, rdfs:'Datatype')
    ;   rdf_equal(O, rdf:'List')
    ),
    !.

axiom_text(Model, rdf(S, P, O), Text) :-
    node_text(Model, S, 4, ST),
    term_text(P, PT),
    node_text(Model, O, 4, OT),
    atomic_list_concat([ST, PT, OT], ' ', Atom),
    atom_string(Atom, Text).

%   node_text(+Model, +Node, +Depth, -Text): a resource or literal as
%   usual, an anonymous class as a short description (Depth levels of
%   nesting, then `[]`).

node_text(Model, Node, Depth, Text) :-
    atom(Node),
    rdf_is_bnode(Node),
    !,
    (   Depth > 0,
        D1 is Depth - 1,
        description(Model, Node, D1, Text0)
    ->  Text = Text0
    ;   Text = '[]'
    ).
node_text(_, Node, _, Text) :-
    term_text(Node, Text).

description(Model, N, D, Text) :-
    value(Model, N, owl:onProperty, P),
    !,
    node_text(Model, P, D, PT),
    (   value(Model, N, owl:hasValue, V)
    ->  node_text(Model, V, D, VT),
        format(atom(Text), '(~w value ~w)', [PT, VT])
    ;   value(Model, N, owl:someValuesFrom, F)
    ->  node_text(Model, F, D, FT),
        format(atom(Text), '(~w some ~w)', [PT, FT])
    ;   value(Model, N, owl:allValuesFrom, F)
    ->  node_text(Model, F, D, FT),
        format(atom(Text), '(~w only ~w)', [PT, FT])
    ;   format(atom(Text), '(~w restriction)', [PT])
    ).
description(Model, N, D, Text) :-
    (   value(Model, N, owl:intersectionOf, L)
    ->  Sep = ' and '
    ;   value(Model, N, owl:unionOf, L)
    ->  Sep = ' or '
    ),
    !,
    list_texts(Model, L, D, Texts),
    atomic_list_concat(Texts, Sep, Inner),
    format(atom(Text), '(~w)', [Inner]).
description(Model, N, D, Text) :-
    value(Model, N, owl:oneOf, L),
    !,
    list_texts(Model, L, D, Texts),
    atomic_list_concat(Texts, ', ', Inner),
    format(atom(Text), '{~w}', [Inner]).
description(Model, N, D, Text) :-
    value(Model, N, owl:complementOf, C),
    !,
    node_text(Model, C, D, CT),
    format(atom(Text), '(not ~w)', [CT]).
description(Model, N, D, Text) :-
    value(Model, N, owl:inverseOf, P),
    !,
    node_text(Model, P, D, PT),
    format(atom(Text), '(inverse ~w)', [PT]).
description(Model, N, _, Text) :-
    value(Model, N, owl:onDatatype, DT),
    !,
    term_text(DT, DTT),
    (   value(Model, N, owl:withRestrictions, L),
        list_members(Model, L, Items)
    ->  findall(FT, ( member(Item, Items),
                      oro_asserted(Model, Item, F, V),
                      facet_text(F, V, FT)
                    ), FTs),
        atomic_list_concat(FTs, ', ', Inner),
        format(atom(Text), '~w[~w]', [DTT, Inner])
    ;   Text = DTT
    ).
description(Model, N, D, Text) :-
    rdf_equal(rdf:first, First),
    oro_asserted(Model, N, First, _),
    !,
    list_texts(Model, N, D, Texts),
    atomic_list_concat(Texts, ' ', Inner),
    format(atom(Text), '(~w)', [Inner]).

:- rdf_meta
    value(+, +, r, -),
    facet_symbol(r, -).

value(Model, N, P, V) :-
    oro_asserted(Model, N, P, V),
    !.

facet_text(F, V, Text) :-
    (   facet_symbol(F, Symbol)
    ->  true
    ;   term_text(F, Symbol)
    ),
    term_text(V, VT),
    format(atom(Text), '~w ~w', [Symbol, VT]).

facet_symbol(xsd:minInclusive, '>=').
facet_symbol(xsd:maxInclusive, '<=').
facet_symbol(xsd:minExclusive, '>').
facet_symbol(xsd:maxExclusive, '<').

list_texts(Model, L, D, Texts) :-
    (   list_members(Model, L, Members)
    ->  maplist(member_text(Model, D), Members, Texts)
    ;   Texts = ['...']
    ).

member_text(Model, D, M, Text) :-
    node_text(Model, M, D, Text).

list_members(Model, L, Members) :-
    list_members(Model, L, 1000, Members).

list_members(_, L, _, []) :-
    rdf_equal(L, rdf:nil),
    !.
list_members(Model, L, Budget, [H|T]) :-
    Budget > 0,
    value(Model, L, rdf:first, H),
    value(Model, L, rdf:rest, R),
    Budget1 is Budget - 1,
    list_members(Model, R, Budget1, T).
